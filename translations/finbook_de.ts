<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>BetweenDrawings</name>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="229"/>
        <source>The first key has no lines to carry.</source>
        <translation>Das erste Schlüsselbild hat keine Linien, die sich übertragen lassen.</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="122"/>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="231"/>
        <source>The second key has no lines to fit to.</source>
        <translation>Das zweite Schlüsselbild hat keine Linien, an die sich anpassen ließe.</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="243"/>
        <source>The first key could not be meshed: %1</source>
        <translation>Das erste Schlüsselbild ließ sich nicht vernetzen: %1</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="279"/>
        <source>The first key&apos;s lines are dots: there is nothing to fit.</source>
        <translation>Die Linien des ersten Schlüsselbilds sind Punkte: Es gibt nichts anzupassen.</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="291"/>
        <source>The first key&apos;s mesh cannot be fitted: %1</source>
        <translation>Das Netz des ersten Schlüsselbilds lässt sich nicht anpassen: %1</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="89"/>
        <source>The lines of the first key around (%1, %2), %3 × %4 px, find nothing like them in the second key.</source>
        <translation>Die Linien des ersten Schlüsselbilds um (%1, %2), %3 × %4 px, finden im zweiten nichts Ähnliches.</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="98"/>
        <source>The first key&apos;s drawing cannot be laid on all of the second&apos;s: its lines around (%1, %2), %3 × %4 px (%5 % of them), have nothing of the first key on them. Draw a key between them, or draw the second closer to the first.</source>
        <translation>Die Zeichnung des ersten Schlüsselbilds lässt sich nicht auf die ganze zweite legen: Deren Linien um (%1, %2), %3 × %4 px (%5 % davon), haben nichts vom ersten Schlüsselbild auf sich. Zeichnen Sie ein Schlüsselbild dazwischen oder das zweite näher am ersten.</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="110"/>
        <source>The two drawings are too different to fit one onto the other (%1 % of the drawing apart on the median, %2 % stretched).%3 Draw a key between them, or draw the second closer to the first.</source>
        <translation>Die beiden Zeichnungen sind zu verschieden, um eine auf die andere anzupassen (im Median %1 % der Zeichnung entfernt, %2 % gedehnt).%3 Zeichnen Sie ein Schlüsselbild dazwischen oder das zweite näher am ersten.</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="120"/>
        <source>A correspondence pin is not on the first key&apos;s drawing.</source>
        <translation>Ein Zuordnungspin liegt nicht auf der Zeichnung des ersten Schlüsselbilds.</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="124"/>
        <source>The fit could not be solved.</source>
        <translation>Die Anpassung ließ sich nicht lösen.</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="139"/>
        <source>The fitted motion cannot be interpolated: %1</source>
        <translation>Die angepasste Bewegung lässt sich nicht interpolieren: %1</translation>
    </message>
</context>
<context>
    <name>CelEditing</name>
    <message>
        <location filename="../ui/src/layers/cel_editing.cpp" line="113"/>
        <source>Cut Cels</source>
        <translation>Zellen ausschneiden</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/cel_editing.cpp" line="141"/>
        <source>No cels have been copied.</source>
        <translation>Es wurden keine Zellen kopiert.</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/cel_editing.cpp" line="149"/>
        <source>The cels cannot go onto a locked layer.</source>
        <translation>Die Zellen können nicht auf eine gesperrte Ebene.</translation>
    </message>
</context>
<context>
    <name>Command</name>
    <message>
        <location filename="../model/src/commands.cpp" line="24"/>
        <source>Draw Stroke</source>
        <translation>Strich zeichnen</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="48"/>
        <source>Erase Stroke</source>
        <translation>Strich radieren</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="77"/>
        <source>Move Strokes to Object</source>
        <translation>Striche in Objekt verschieben</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="172"/>
        <source>New Object</source>
        <translation>Neues Objekt</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="200"/>
        <source>Delete Object</source>
        <translation>Objekt löschen</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="229"/>
        <source>Rename Object</source>
        <translation>Objekt umbenennen</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="254"/>
        <source>Reorder Object</source>
        <translation>Objekt umsortieren</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="285"/>
        <source>Show Object</source>
        <translation>Objekt einblenden</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="285"/>
        <source>Hide Object</source>
        <translation>Objekt ausblenden</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="287"/>
        <source>Lock Object</source>
        <translation>Objekt sperren</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="287"/>
        <source>Unlock Object</source>
        <translation>Objekt entsperren</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="321"/>
        <source>Insert Frame</source>
        <translation>Einzelbild einfügen</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="325"/>
        <location filename="../model/src/scene/layer_commands.cpp" line="25"/>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="346"/>
        <source>Duplicate Frame</source>
        <translation>Einzelbild duplizieren</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="365"/>
        <location filename="../model/src/scene/layer_commands.cpp" line="413"/>
        <source>Paste Cels</source>
        <translation>Zellen einfügen</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="420"/>
        <source>Delete Frame</source>
        <translation>Einzelbild löschen</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="447"/>
        <source>Move Frame</source>
        <translation>Einzelbild verschieben</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="471"/>
        <source>Change Frame Exposure</source>
        <translation>Haltedauer des Einzelbilds ändern</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="515"/>
        <source>Change Document Settings</source>
        <translation>Dokumenteinstellungen ändern</translation>
    </message>
    <message>
        <location filename="../model/src/object_commands.cpp" line="28"/>
        <source>“%1” has lines under the picture of “%2”: one object draws its picture under its lines, so merged they would cover it. Put the picture below them first (Object → Send Backward).</source>
        <translation>„%1“ hat Linien unter dem Bild von „%2“: Ein Objekt zeichnet sein Bild unter seine Linien, zusammengeführt würden sie es also verdecken. Legen Sie das Bild zuerst darunter (Objekt → Nach hinten stellen).</translation>
    </message>
    <message>
        <location filename="../model/src/object_commands.cpp" line="43"/>
        <source>Merge Objects</source>
        <translation>Objekte zusammenführen</translation>
    </message>
    <message>
        <location filename="../model/src/pins/pin_commands.cpp" line="56"/>
        <source>Add Pin</source>
        <translation>Pin setzen</translation>
    </message>
    <message>
        <location filename="../model/src/pins/pin_commands.cpp" line="64"/>
        <source>Remove Pin</source>
        <translation>Pin entfernen</translation>
    </message>
    <message>
        <location filename="../model/src/pins/pin_commands.cpp" line="74"/>
        <source>Move Pin</source>
        <translation>Pin verschieben</translation>
    </message>
    <message>
        <location filename="../model/src/pins/pin_commands.cpp" line="88"/>
        <source>Change Mesh Density</source>
        <translation>Netzdichte ändern</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_commands.cpp" line="49"/>
        <source>Place Cage</source>
        <translation>Käfig platzieren</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_commands.cpp" line="56"/>
        <source>Edit Cage</source>
        <translation>Käfig bearbeiten</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_commands.cpp" line="67"/>
        <source>Move Cage Corners</source>
        <translation>Käfigecken verschieben</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_commands.cpp" line="75"/>
        <source>Remove Rig</source>
        <translation>Rig entfernen</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/inbetween_commands.cpp" line="17"/>
        <location filename="../model/src/inbetween/inbetween_commands.cpp" line="29"/>
        <source>Generate In-betweens</source>
        <translation>Zwischenbilder erzeugen</translation>
    </message>
    <message>
        <location filename="../model/src/rig/rig_commands.cpp" line="92"/>
        <source>Reset Pose</source>
        <translation>Pose zurücksetzen</translation>
    </message>
    <message>
        <location filename="../model/src/rig/rig_commands.cpp" line="220"/>
        <location filename="../model/src/skeleton/skeleton_join_commands.cpp" line="199"/>
        <source>Apply Pose to Drawing</source>
        <translation>Pose auf Zeichnung anwenden</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="78"/>
        <source>Build Skeleton</source>
        <translation>Skelett erstellen</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="89"/>
        <source>Change Skeleton Settings</source>
        <translation>Skeletteinstellungen ändern</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="117"/>
        <source>Pose Bones</source>
        <translation>Knochen posieren</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="126"/>
        <source>Change Skinning</source>
        <translation>Skinning ändern</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="143"/>
        <source>Lock Joint</source>
        <translation>Gelenk sperren</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="143"/>
        <source>Unlock Joint</source>
        <translation>Gelenk entsperren</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="170"/>
        <source>Reset Bone Pose</source>
        <translation>Knochenpose zurücksetzen</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="182"/>
        <source>Move Joint</source>
        <translation>Gelenk verschieben</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="205"/>
        <source>Insert Joint</source>
        <translation>Gelenk einfügen</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="218"/>
        <source>Delete Joint</source>
        <translation>Gelenk löschen</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_join_commands.cpp" line="106"/>
        <source>Join Part</source>
        <translation>Teil verbinden</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_join_commands.cpp" line="130"/>
        <source>Detach Part</source>
        <translation>Teil lösen</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_join_commands.cpp" line="135"/>
        <source>Join Overlapping Parts</source>
        <translation>Überlappende Teile verbinden</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_join_commands.cpp" line="166"/>
        <source>Make Character Root</source>
        <translation>Zur Wurzel der Figur machen</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_commands.cpp" line="92"/>
        <source>Recolour Fill</source>
        <translation>Füllung umfärben</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_commands.cpp" line="92"/>
        <source>Fill Region</source>
        <translation>Bereich füllen</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_commands.cpp" line="101"/>
        <source>Remove Fill</source>
        <translation>Füllung entfernen</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_commands.cpp" line="112"/>
        <source>Fill All Enclosed Regions</source>
        <translation>Alle geschlossenen Bereiche füllen</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_commands.cpp" line="123"/>
        <source>Close Gaps</source>
        <translation>Lücken schließen</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_commands.cpp" line="18"/>
        <source>Import Sound</source>
        <translation>Ton importieren</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_commands.cpp" line="37"/>
        <source>Delete Sound</source>
        <translation>Ton löschen</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_commands.cpp" line="77"/>
        <source>Move Sound</source>
        <translation>Ton verschieben</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_commands.cpp" line="79"/>
        <source>Change Sound Volume</source>
        <translation>Lautstärke ändern</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_commands.cpp" line="83"/>
        <source>Mute Sound</source>
        <translation>Ton stummschalten</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_commands.cpp" line="83"/>
        <source>Unmute Sound</source>
        <translation>Stummschaltung aufheben</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_commands.cpp" line="19"/>
        <source>Shade Fills</source>
        <translation>Füllungen schattieren</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_commands.cpp" line="19"/>
        <source>Unshade Fills</source>
        <translation>Schattierung der Füllungen entfernen</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_commands.cpp" line="46"/>
        <source>Move Light</source>
        <translation>Licht verschieben</translation>
    </message>
    <message>
        <location filename="../model/src/erase/stroke_cut.cpp" line="162"/>
        <source>Keep Fills Along a Cut</source>
        <translation>Füllungen entlang eines Schnitts behalten</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_commands.cpp" line="60"/>
        <source>Change Camera Key</source>
        <translation>Kamera-Schlüsselbild ändern</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_commands.cpp" line="60"/>
        <source>Add Camera Key</source>
        <translation>Kamera-Schlüsselbild hinzufügen</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_commands.cpp" line="66"/>
        <source>Delete Camera Key</source>
        <translation>Kamera-Schlüsselbild löschen</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_commands.cpp" line="77"/>
        <source>Move Camera Key</source>
        <translation>Kamera-Schlüsselbild verschieben</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="17"/>
        <source>New Layer</source>
        <translation>Neue Ebene</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="47"/>
        <source>Duplicate Layer</source>
        <translation>Ebene duplizieren</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="56"/>
        <source>%1 copy</source>
        <translation>%1 Kopie</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="77"/>
        <source>Delete Layer</source>
        <translation>Ebene löschen</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="104"/>
        <source>Move Layer</source>
        <translation>Ebene verschieben</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="168"/>
        <source>Insert Time</source>
        <translation>Zeit einfügen</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="185"/>
        <source>Delete Time</source>
        <translation>Zeit löschen</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="222"/>
        <location filename="../model/src/scene/layer_commands.cpp" line="342"/>
        <source>Move Cels</source>
        <translation>Zellen verschieben</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="252"/>
        <source>Insert Empty Cel</source>
        <translation>Leere Zelle einfügen</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="342"/>
        <source>Copy Cels</source>
        <translation>Zellen kopieren</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="430"/>
        <source>Delete Cels</source>
        <translation>Zellen löschen</translation>
    </message>
    <message>
        <location filename="../model/src/document.cpp" line="21"/>
        <location filename="../model/src/document.cpp" line="226"/>
        <location filename="../model/src/finbook_file_io.cpp" line="226"/>
        <source>Layer 1</source>
        <translation>Ebene 1</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_keys.cpp" line="83"/>
        <source>The object is not swappable: make a mouth chart first (Object &gt; New Mouth Chart).</source>
        <translation>Das Objekt ist nicht austauschbar: Legen Sie zuerst eine Mundtabelle an (Objekt &gt; Neue Mundtabelle).</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_keys.cpp" line="89"/>
        <source>The set &quot;%1&quot; has no drawings named A to F (the mouth shapes lip sync keys): make a mouth chart, or name its drawings by their shapes.</source>
        <translation>Der Satz „%1“ hat keine Zeichnungen namens A bis F (die Mundformen der Lippensynchronisation): Legen Sie eine Mundtabelle an oder benennen Sie die Zeichnungen nach ihren Formen.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_keys.cpp" line="96"/>
        <source>There is nothing to key.</source>
        <translation>Es gibt nichts zu setzen.</translation>
    </message>
    <message>
        <location filename="../model/src/swap/mouth_chart.cpp" line="88"/>
        <source>A (M B P)</source>
        <translation>A (M B P)</translation>
    </message>
    <message>
        <location filename="../model/src/swap/mouth_chart.cpp" line="88"/>
        <source>B (K S T)</source>
        <translation>B (K S T)</translation>
    </message>
    <message>
        <location filename="../model/src/swap/mouth_chart.cpp" line="89"/>
        <source>C (EH AE)</source>
        <translation>C (EH AE)</translation>
    </message>
    <message>
        <location filename="../model/src/swap/mouth_chart.cpp" line="89"/>
        <source>D (AA)</source>
        <translation>D (AA)</translation>
    </message>
    <message>
        <location filename="../model/src/swap/mouth_chart.cpp" line="90"/>
        <source>E (AO ER)</source>
        <translation>E (AO ER)</translation>
    </message>
    <message>
        <location filename="../model/src/swap/mouth_chart.cpp" line="90"/>
        <source>F (UW OW W)</source>
        <translation>F (UW OW W)</translation>
    </message>
    <message>
        <location filename="../model/src/swap/mouth_chart.cpp" line="91"/>
        <source>G (F V)</source>
        <translation>G (F V)</translation>
    </message>
    <message>
        <location filename="../model/src/swap/mouth_chart.cpp" line="91"/>
        <source>H (L)</source>
        <translation>H (L)</translation>
    </message>
    <message>
        <location filename="../model/src/swap/mouth_chart.cpp" line="92"/>
        <source>X (rest)</source>
        <translation>X (Ruhe)</translation>
    </message>
    <message>
        <location filename="../model/src/swap/mouth_chart.cpp" line="116"/>
        <source>Mouth</source>
        <translation>Mund</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="64"/>
        <source>Make Object Swappable</source>
        <translation>Objekt austauschbar machen</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="90"/>
        <source>New Swap Set</source>
        <translation>Neuer Austauschsatz</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="139"/>
        <source>Show Drawing &quot;%1&quot;</source>
        <translation>Zeichnung „%1“ zeigen</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="218"/>
        <source>New Drawing &quot;%1&quot;</source>
        <translation>Neue Zeichnung „%1“</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="270"/>
        <source>Rename Drawing</source>
        <translation>Zeichnung umbenennen</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="300"/>
        <source>Delete Drawing &quot;%1&quot;</source>
        <translation>Zeichnung „%1“ löschen</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="334"/>
        <source>Make Drawing Independent</source>
        <translation>Zeichnung eigenständig machen</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_commands.cpp" line="18"/>
        <source>Import Picture</source>
        <translation>Bild importieren</translation>
    </message>
    <message>
        <location filename="../model/src/fill/uncovered_lines.cpp" line="266"/>
        <source>Show Lines</source>
        <translation>Linien zeigen</translation>
    </message>
</context>
<context>
    <name>CommandLine</name>
    <message>
        <location filename="../app/cli.cpp" line="193"/>
        <source>No command given; see finbook --help.</source>
        <translation>Kein Befehl angegeben; siehe finbook --help.</translation>
    </message>
    <message>
        <location filename="../app/cli.cpp" line="197"/>
        <source>Usage: finbook info FILE</source>
        <translation>Aufruf: finbook info FILE</translation>
    </message>
    <message>
        <location filename="../app/cli.cpp" line="217"/>
        <source>Unknown command &quot;%1&quot;; see finbook --help.</source>
        <translation>Unbekannter Befehl „%1“; siehe finbook --help.</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="40"/>
        <source>Finbook, a flipbook animation editor.

  finbook [FILE]               open FILE in the editor
  finbook info FILE            print a JSON summary of FILE
  finbook export FILE OUTDIR   render every frame to OUTDIR/frame_0001.png ...
  finbook export FILE OUT      export to OUT.gif, .mp4, .webm, .apng or .html
  finbook export FILE OUT.obj --frame N   frame N as a 3D model (OUT.obj, OUT.mtl)
  finbook export FILE OUT.glb --frame N   frame N as a 3D model (glTF binary)
  finbook export FILE... --format F --out-dir DIR   export several files
  finbook thumbnail FILE OUT.png SIZE   write the first frame as a PNG of at most SIZE px</source>
        <translation>Finbook, ein Daumenkino-Animationseditor.

  finbook [FILE]               FILE im Editor öffnen
  finbook info FILE            eine JSON-Zusammenfassung von FILE ausgeben
  finbook export FILE OUTDIR   jedes Einzelbild nach OUTDIR/frame_0001.png ... rendern
  finbook export FILE OUT      nach OUT.gif, .mp4, .webm, .apng oder .html exportieren
  finbook export FILE OUT.obj --frame N   Einzelbild N als 3D-Modell (OUT.obj, OUT.mtl)
  finbook export FILE OUT.glb --frame N   Einzelbild N als 3D-Modell (glTF binär)
  finbook export FILE... --format F --out-dir DIR   mehrere Dateien exportieren
  finbook thumbnail FILE OUT.png SIZE   das erste Einzelbild als PNG von höchstens SIZE px schreiben</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="56"/>
        <source>Use LANGUAGE (e.g. de, en, fr, ja) instead of the system&apos;s.</source>
        <translation>LANGUAGE (z. B. de, en, fr, ja) statt der Systemsprache verwenden.</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="62"/>
        <source>FILE, or a command.</source>
        <translation>FILE oder ein Befehl.</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="74"/>
        <source>see finbook --help</source>
        <comment>after an error</comment>
        <translation>siehe finbook --help</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="81"/>
        <source>%1; %2.</source>
        <comment>an argument error from Qt, then &quot;see finbook --help&quot;</comment>
        <translation>%1; %2.</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="117"/>
        <source>Unknown command &quot;%1&quot;; %2.</source>
        <translation>Unbekannter Befehl „%1“; %2.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="43"/>
        <source>export: frames A to B (default: the play range).</source>
        <translation>export: Einzelbilder A bis B (Standard: der Wiedergabebereich).</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="39"/>
        <source>export: png, svg, gif, mp4, webm, apng, html, obj, glb, json (Lottie) or lottie (dotLottie).</source>
        <translation>export: png, svg, gif, mp4, webm, apng, html, obj, glb, json (Lottie) oder lottie (dotLottie).</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="45"/>
        <source>export: frame N only; a 3D model (obj, glb) is one frame, by default the first of the play range.</source>
        <translation>export: nur Einzelbild N; ein 3D-Modell (obj, glb) ist ein Einzelbild, standardmäßig das erste des Abspielbereichs.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="48"/>
        <source>export: multiply the canvas size by S.</source>
        <translation>export: die Leinwandgröße mit S multiplizieren.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="50"/>
        <source>export: N frames per second (default: the document&apos;s).</source>
        <translation>export: N Bilder pro Sekunde (Standard: die des Dokuments).</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="52"/>
        <source>export: this background colour (#rrggbb).</source>
        <translation>export: diese Hintergrundfarbe (#rrggbb).</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="53"/>
        <source>export: no background.</source>
        <translation>export: kein Hintergrund.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="55"/>
        <source>export png/svg: one file per drawing plus an exposure sheet.</source>
        <translation>export png/svg: eine Datei pro Zeichnung plus ein Timing-Sheet.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="58"/>
        <source>export: paint the document&apos;s reference picture or video under the drawing.</source>
        <translation>export: das Referenzbild oder -video des Dokuments unter die Zeichnung malen.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="62"/>
        <source>export: the whole page, not the shot the document&apos;s camera frames.</source>
        <translation>export: die ganze Seite statt des Ausschnitts, den die Kamera des Dokuments zeigt.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="65"/>
        <source>export: only the layers named A, B, ... (hidden ones too), not every visible layer.</source>
        <translation>export: nur die Ebenen namens A, B, ... (auch ausgeblendete) statt aller sichtbaren Ebenen.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="69"/>
        <source>export: fail (exit code 2, nothing written) when a sound clip or the reference cannot be used, instead of leaving it out with a warning.</source>
        <translation>export: abbrechen (Exit-Code 2, nichts geschrieben), wenn ein Soundclip oder die Referenz nicht verwendet werden kann, statt sie mit einer Warnung wegzulassen.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="72"/>
        <source>export: replace existing files.</source>
        <translation>export: vorhandene Dateien ersetzen.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="73"/>
        <source>export: write each FILE into DIR.</source>
        <translation>export: jede Datei (FILE) in DIR schreiben.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="75"/>
        <source>export: allow up to N frames (default: 100000 files, 3 hours of video).</source>
        <translation>export: bis zu N Einzelbilder erlauben (Standard: 100000 Dateien, 3 Stunden Video).</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="107"/>
        <source>--range needs A-B with 1 &lt;= A &lt;= B, not &quot;%1&quot;.</source>
        <translation>--range erwartet A-B mit 1 &lt;= A &lt;= B, nicht „%1“.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="121"/>
        <source>--frame and --range cannot be used together.</source>
        <translation>--frame und --range können nicht zusammen verwendet werden.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="124"/>
        <source>--frame needs a frame number from 1, not &quot;%1&quot;.</source>
        <translation>--frame braucht eine Bildnummer ab 1, nicht „%1“.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="131"/>
        <source>--scale needs a number above 0, not &quot;%1&quot;.</source>
        <translation>--scale erwartet eine Zahl größer als 0, nicht „%1“.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="137"/>
        <source>--fps needs a whole number from %1 to %2, not &quot;%3&quot;.</source>
        <translation>--fps erwartet eine ganze Zahl von %1 bis %2, nicht „%3“.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="145"/>
        <source>--max-frames needs a whole number above 0, not &quot;%1&quot;.</source>
        <translation>--max-frames erwartet eine ganze Zahl größer als 0, nicht „%1“.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="151"/>
        <source>--background needs a colour such as #ffffff, not &quot;%1&quot;.</source>
        <translation>--background erwartet eine Farbe wie #ffffff, nicht „%1“.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="163"/>
        <source>Unknown export format &quot;%1&quot;; use png, svg, gif, mp4, webm, apng, html, obj, glb, json (Lottie) or lottie (dotLottie).</source>
        <translation>Unbekanntes Exportformat „%1“; verwenden Sie png, svg, gif, mp4, webm, apng, html, obj, glb, json (Lottie) oder lottie (dotLottie).</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="186"/>
        <source>Cannot tell the format from &quot;%1&quot;: end it in .gif, .mp4, .webm, .apng, .html, .obj, .glb, .json (Lottie) or .lottie, give a folder for PNG frames, or use --format.</source>
        <translation>Das Format lässt sich aus „%1“ nicht ermitteln: Lassen Sie den Namen auf .gif, .mp4, .webm, .apng, .html, .obj, .glb, .json (Lottie) oder .lottie enden, geben Sie einen Ordner für PNG-Einzelbilder an oder verwenden Sie --format.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="179"/>
        <source>&quot;%1&quot; is a folder, not a %2 file; give a file name, or --format png to write PNG frames into the folder.</source>
        <translation>„%1“ ist ein Ordner, keine %2-Datei; geben Sie einen Dateinamen an oder --format png, um PNG-Einzelbilder in den Ordner zu schreiben.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="191"/>
        <source>--format %1 does not match &quot;%2&quot;.</source>
        <translation>--format %1 passt nicht zu „%2“.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="207"/>
        <source>Usage: finbook export FILE OUT, or finbook export FILE... --out-dir DIR</source>
        <translation>Aufruf: finbook export FILE OUT oder finbook export FILE... --out-dir DIR</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="211"/>
        <source>Usage: finbook export FILE... --out-dir DIR</source>
        <translation>Aufruf: finbook export FILE... --out-dir DIR</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="228"/>
        <source>--layers needs the names of layers, separated by commas.</source>
        <translation>--layers braucht die Namen von Ebenen, durch Kommas getrennt.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="231"/>
        <source>--transparent and --background cannot be used together.</source>
        <translation>--transparent und --background können nicht zusammen verwendet werden.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="233"/>
        <source>--one-per-drawing is for png and svg exports only.</source>
        <translation>--one-per-drawing gilt nur für png- und svg-Exporte.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="329"/>
        <source>Could not write &quot;%1&quot;: %2. Nothing was exported.</source>
        <translation>„%1“ konnte nicht geschrieben werden: %2. Es wurde nichts exportiert.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="344"/>
        <source>&quot;%1&quot; has no layer named &quot;%2&quot;; its layers are %3. Nothing was exported.</source>
        <translation>„%1“ hat keine Ebene namens „%2“; seine Ebenen sind %3. Es wurde nichts exportiert.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="360"/>
        <source>Interrupted; nothing was exported.</source>
        <translation>Unterbrochen; es wurde nichts exportiert.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="368"/>
        <source>Use --overwrite to replace it.</source>
        <translation>Verwenden Sie --overwrite, um sie zu ersetzen.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="370"/>
        <source>Use --max-frames N to allow N frames.</source>
        <translation>Mit --max-frames N werden N Einzelbilder erlaubt.</translation>
    </message>
</context>
<context>
    <name>Deformation</name>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="127"/>
        <source>The object has no strokes to deform.</source>
        <translation>Das Objekt hat keine Striche, die sich verformen ließen.</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="134"/>
        <source>This drawing cannot be meshed for deformation: %1</source>
        <translation>Für diese Zeichnung lässt sich kein Verformungsnetz erstellen: %1</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="166"/>
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="217"/>
        <source>The cage changed while it was being prepared.</source>
        <translation>Der Käfig wurde geändert, während er vorbereitet wurde.</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="225"/>
        <source>The object has no mesh to deform.</source>
        <translation>Das Objekt hat kein Netz, das sich verformen ließe.</translation>
    </message>
    <message>
        <location filename="../model/src/pins/pin_setup.cpp" line="20"/>
        <source>The pins cannot be solved on this drawing: %1</source>
        <translation>Die Pins lassen sich auf dieser Zeichnung nicht berechnen: %1</translation>
    </message>
    <message>
        <location filename="../model/src/pins/pin_setup.cpp" line="49"/>
        <source>The pins could not be solved: %1</source>
        <translation>Die Pins konnten nicht berechnet werden: %1</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="248"/>
        <source>The deformation produced invalid points; it was not applied.</source>
        <translation>Die Verformung hat ungültige Punkte ergeben; sie wurde nicht angewendet.</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_setup.cpp" line="35"/>
        <source>The cage cannot be used: %1</source>
        <translation>Der Käfig kann nicht verwendet werden: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/cage/cage_setup.cpp" line="41"/>
        <source>%n stroke point(s) lie outside the cage; move its corners out so it encloses the drawing.</source>
        <translation>
            <numerusform>%n Strichpunkt liegt außerhalb des Käfigs; ziehen Sie seine Ecken nach außen, damit er die Zeichnung umschließt.</numerusform>
            <numerusform>%n Strichpunkte liegen außerhalb des Käfigs; ziehen Sie seine Ecken nach außen, damit er die Zeichnung umschließt.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_setup.cpp" line="44"/>
        <source>The drawing cannot be bound to the cage: %1</source>
        <translation>Die Zeichnung kann nicht an den Käfig gebunden werden: %1</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_setup.cpp" line="59"/>
        <location filename="../model/src/cage/cage_setup.cpp" line="62"/>
        <source>The cage could not be solved: %1</source>
        <translation>Der Käfig konnte nicht berechnet werden: %1</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_setup.cpp" line="72"/>
        <source>This cage cannot be used: %1</source>
        <translation>Dieser Käfig kann nicht verwendet werden: %1</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_setup.cpp" line="76"/>
        <source>The cage must enclose the whole object: %1</source>
        <translation>Der Käfig muss das ganze Objekt umschließen: %1</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_setup.cpp" line="99"/>
        <source>No cage fits this drawing: %1</source>
        <translation>Kein Käfig passt zu dieser Zeichnung: %1</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_build.cpp" line="42"/>
        <source>No skeleton can be built for this drawing: %1</source>
        <translation>Für diese Zeichnung lässt sich kein Skelett erstellen: %1</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_build.cpp" line="55"/>
        <source>The object has no strokes to build a skeleton in.</source>
        <translation>Das Objekt hat keine Striche, in denen sich ein Skelett erstellen ließe.</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_build.cpp" line="73"/>
        <location filename="../model/src/skeleton/skeleton_build.cpp" line="88"/>
        <source>No skeleton can be built for this drawing.</source>
        <translation>Für diese Zeichnung lässt sich kein Skelett erstellen.</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="27"/>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="93"/>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="136"/>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="165"/>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="188"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="23"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="67"/>
        <source>The skeleton is damaged; build it again.</source>
        <translation>Das Skelett ist beschädigt; erstellen Sie es neu.</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="29"/>
        <source>Reset the pose or apply it to the drawing before editing joints.</source>
        <translation>Setzen Sie die Pose zurück oder wenden Sie sie auf die Zeichnung an, bevor Sie Gelenke bearbeiten.</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="31"/>
        <source>There is no such joint.</source>
        <translation>Dieses Gelenk gibt es nicht.</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="50"/>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="64"/>
        <source>A joint cannot go there.</source>
        <translation>Dorthin kann kein Gelenk.</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="62"/>
        <source>A joint can only be inserted on a bone.</source>
        <translation>Ein Gelenk kann nur auf einem Knochen eingefügt werden.</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="69"/>
        <source>The bone is too short to split.</source>
        <translation>Der Knochen ist zu kurz zum Teilen.</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="102"/>
        <source>A skeleton needs at least one bone.</source>
        <translation>Ein Skelett braucht mindestens einen Knochen.</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="34"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="57"/>
        <source>The skeleton cannot be used: %1</source>
        <translation>Das Skelett kann nicht verwendet werden: %1</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="123"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="138"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="168"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="178"/>
        <source>The skeleton cannot skin this drawing: %1</source>
        <translation>Das Skelett kann nicht an diese Zeichnung gebunden werden: %1</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="73"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="295"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="299"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="305"/>
        <source>The bones could not be posed: %1</source>
        <translation>Die Knochen konnten nicht posiert werden: %1</translation>
    </message>
</context>
<context>
    <name>Export</name>
    <message>
        <location filename="../model/src/export/export_encoded.cpp" line="43"/>
        <location filename="../model/src/export/export_encoded.cpp" line="71"/>
        <location filename="../model/src/export/export_flipbook.cpp" line="215"/>
        <location filename="../model/src/export/export_sequence.cpp" line="101"/>
        <source>there is not enough memory to render it</source>
        <translation>es ist nicht genug Speicher vorhanden, um es zu rendern</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="53"/>
        <source>its folder cannot be created</source>
        <translation>ihr Ordner kann nicht angelegt werden</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_encoded.cpp" line="169"/>
        <source>ffmpeg finished without writing the %1; nothing was exported.</source>
        <translation>ffmpeg wurde beendet, ohne die Ausgabe als %1 zu schreiben; es wurde nichts exportiert.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_flipbook.cpp" line="168"/>
        <source>Flipbook</source>
        <translation>Daumenkino</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_flipbook.cpp" line="180"/>
        <location filename="../model/src/export/export_flipbook.cpp" line="191"/>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_flipbook.cpp" line="182"/>
        <source>Loop</source>
        <translation>Endlosschleife</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_flipbook.cpp" line="185"/>
        <source>Frame</source>
        <translation>Einzelbild</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_flipbook.cpp" line="192"/>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="46"/>
        <source>The frame range %1-%2 is not within the animation&apos;s frames 1-%3; choose a range inside it.</source>
        <translation>Der Einzelbildbereich %1–%2 liegt nicht innerhalb der Einzelbilder 1–%3 der Animation; wählen Sie einen Bereich darin.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="80"/>
        <source>The camera moves while a drawing is held, so one file per drawing cannot show the shot; export one file per frame, or without the camera.</source>
        <translation>Die Kamera bewegt sich, während eine Zeichnung gehalten wird, daher kann eine Datei pro Zeichnung den Ausschnitt nicht zeigen; exportieren Sie eine Datei pro Bild oder ohne die Kamera.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="116"/>
        <source>The animation has no frames to export.</source>
        <translation>Die Animation hat keine Einzelbilder, die sich exportieren ließen.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="118"/>
        <source>The canvas has no size; set one in Document Settings.</source>
        <translation>Die Leinwand hat keine Größe; legen Sie eine in den Dokumenteinstellungen fest.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="126"/>
        <source>A 3D model holds one frame, not the frames %1-%2; choose a single frame.</source>
        <translation>Ein 3D-Modell enthält ein Einzelbild, nicht die Bilder %1–%2; wählen Sie ein einzelnes Bild.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="146"/>
        <source>The scale %1 is not a size a picture can have; choose a scale that gives 1 to %2 pixels a side.</source>
        <translation>Die Skalierung %1 ergibt keine mögliche Bildgröße; wählen Sie eine Skalierung, die 1 bis %2 Pixel pro Seite ergibt.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="150"/>
        <source>The scale %1 would make a %2 x %3 pixel picture; choose a scale that gives 1 to %4 pixels a side.</source>
        <translation>Die Skalierung %1 ergäbe ein Bild mit %2 × %3 Pixeln; wählen Sie eine Skalierung, die 1 bis %4 Pixel pro Seite ergibt.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="163"/>
        <source>The frame rate %1 is not possible; choose %2 to %3 frames per second.</source>
        <translation>Die Bildrate %1 ist nicht möglich; wählen Sie %2 bis %3 Bilder pro Sekunde.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="171"/>
        <source>%1 video cannot be transparent; choose WebM, APNG, GIF or PNG for a transparent background.</source>
        <translation>%1-Videos können nicht transparent sein; wählen Sie WebM, APNG, GIF oder PNG für einen transparenten Hintergrund.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="199"/>
        <source>This export would write %1 frames, more than the %2 allowed; nothing was exported.</source>
        <translation>Dieser Export würde %1 Einzelbilder schreiben, mehr als die erlaubten %2; es wurde nichts exportiert.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="206"/>
        <source>This export would write %1 files (%2 playback ticks), more than %3 without your explicit permission; nothing was exported.</source>
        <translation>Dieser Export würde %1 Dateien schreiben (%2 Wiedergabeschritte), mehr als %3 ohne Ihre ausdrückliche Erlaubnis; es wurde nichts exportiert.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="214"/>
        <source>This export would make %1 hours of animation (%2 frames), more than %3 hours without your explicit permission; nothing was exported.</source>
        <translation>Dieser Export würde %1 Stunden Animation ergeben (%2 Einzelbilder), mehr als %3 Stunden ohne Ihre ausdrückliche Erlaubnis; es wurde nichts exportiert.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_sequence.cpp" line="68"/>
        <source>&quot;%1&quot; is a folder where a file should go; choose another folder.</source>
        <translation>„%1“ ist ein Ordner, wo eine Datei hingehört; wählen Sie einen anderen Ordner.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_sequence.cpp" line="119"/>
        <source>&quot;%1&quot; is a file, not a folder; choose a folder for the %2 files, or remove the file.</source>
        <translation>„%1“ ist eine Datei, kein Ordner; wählen Sie einen Ordner für die %2-Dateien oder entfernen Sie die Datei.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_sequence.cpp" line="128"/>
        <source>&quot;%1&quot; is the top folder of the disk; choose or name a folder for the frames, such as &quot;%2&quot;.</source>
        <translation>„%1“ ist der oberste Ordner des Datenträgers; wählen oder benennen Sie einen Ordner für die Einzelbilder, etwa „%2“.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_sequence.cpp" line="137"/>
        <source>the folder cannot be created</source>
        <translation>der Ordner kann nicht angelegt werden</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="23"/>
        <source>&quot;%1&quot; already exists; nothing was exported.</source>
        <translation>„%1“ ist bereits vorhanden; es wurde nichts exportiert.</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="30"/>
        <source>Could not write &quot;%1&quot;: %2. Nothing was exported; free some disk space or choose another folder, then export again.</source>
        <translation>„%1“ konnte nicht geschrieben werden: %2. Es wurde nichts exportiert; geben Sie Speicherplatz frei oder wählen Sie einen anderen Ordner und exportieren Sie dann erneut.</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="38"/>
        <source>The export was cancelled; nothing was written.</source>
        <translation>Der Export wurde abgebrochen; es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="44"/>
        <source>Another export is writing to &quot;%1&quot;; wait until it has finished, or choose another target.</source>
        <translation>Ein anderer Export schreibt gerade nach „%1“; warten Sie, bis er fertig ist, oder wählen Sie ein anderes Ziel.</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="113"/>
        <source>&quot;%1&quot; is a folder; give a file name ending in .%2.</source>
        <translation>„%1“ ist ein Ordner; geben Sie einen Dateinamen an, der auf .%2 endet.</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="254"/>
        <source>Choose where to export the animation to.</source>
        <translation>Wählen Sie, wohin die Animation exportiert werden soll.</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/export/exporter.cpp" line="268"/>
        <source>%n more sound clip(s) are left out too.</source>
        <translation>
            <numerusform>%n weiterer Soundclip wird ebenfalls weggelassen.</numerusform>
            <numerusform>%n weitere Soundclips werden ebenfalls weggelassen.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="275"/>
        <source>Nothing was exported.</source>
        <translation>Es wurde nichts exportiert.</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_arguments.cpp" line="41"/>
        <source>GIF</source>
        <translation>GIF</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_arguments.cpp" line="70"/>
        <source>MP4 video</source>
        <translation>MP4-Video</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_arguments.cpp" line="88"/>
        <source>WebM video</source>
        <translation>WebM-Video</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_arguments.cpp" line="102"/>
        <source>animated PNG</source>
        <translation>animiertes PNG</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_encoder.cpp" line="175"/>
        <source>Exporting %1 needs the ffmpeg program, which was not found; install it (on Debian: apt install ffmpeg) and export again.</source>
        <translation>Für den Export als %1 wird das Programm ffmpeg benötigt, das nicht gefunden wurde; installieren Sie es (unter Debian: apt install ffmpeg) und exportieren Sie erneut.</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_encoder.cpp" line="268"/>
        <source>it stopped unexpectedly</source>
        <translation>es wurde unerwartet beendet</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_encoder.cpp" line="269"/>
        <source>exit code %1</source>
        <translation>Exit-Code %1</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_encoder.cpp" line="272"/>
        <source>ffmpeg could not make the %1 (%2); nothing was written. If the disk is full, free some space and export again.</source>
        <translation>ffmpeg konnte die Ausgabe als %1 nicht erstellen (%2); es wurde nichts geschrieben. Falls der Datenträger voll ist, geben Sie Speicherplatz frei und exportieren Sie erneut.</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/export/ffmpeg_encoder.cpp" line="283"/>
        <source>ffmpeg made no progress for %n second(s) and was stopped; nothing was written. Check that ffmpeg works, then export again.</source>
        <translation>
            <numerusform>ffmpeg kam %n Sekunde lang nicht voran und wurde beendet; es wurde nichts geschrieben. Prüfen Sie, ob ffmpeg funktioniert, und exportieren Sie erneut.</numerusform>
            <numerusform>ffmpeg kam %n Sekunden lang nicht voran und wurde beendet; es wurde nichts geschrieben. Prüfen Sie, ob ffmpeg funktioniert, und exportieren Sie erneut.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/export/pending_output.cpp" line="341"/>
        <source>a folder cannot be created in it</source>
        <translation>darin kann kein Ordner angelegt werden</translation>
    </message>
    <message>
        <location filename="../model/src/export/pending_output.cpp" line="362"/>
        <source>&quot;%1&quot; is a folder where a file should go</source>
        <translation>„%1“ ist ein Ordner, wo eine Datei hingehört</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_model.cpp" line="68"/>
        <source>The 3D model of frame %1 would have more than %L2 vertices, the most a 3D export writes (about 25 MB of glTF). Nothing was exported; lower the mesh density of its objects (Deform → Mesh Density) or hide some of them.</source>
        <translation>Das 3D-Modell von Einzelbild %1 hätte mehr als %L2 Eckpunkte, mehr als ein 3D-Export schreibt (etwa 25 MB glTF). Es wurde nichts exportiert; verringern Sie die Netzdichte seiner Objekte (Verformen → Netzdichte) oder blenden Sie einige aus.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_model.cpp" line="79"/>
        <source>Frame %1 shows no drawing to make a 3D model of; choose another frame.</source>
        <translation>Einzelbild %1 zeigt keine Zeichnung, aus der sich ein 3D-Modell machen ließe; wählen Sie ein anderes Bild.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_model.cpp" line="84"/>
        <source>No object of frame %1 can be made 3D: their points lie more than %L2 pixels from the page, too far out to mesh. Nothing was exported; move the drawing back onto the page or choose another frame.</source>
        <translation>Kein Objekt von Einzelbild %1 lässt sich in 3D umwandeln: Seine Punkte liegen mehr als %L2 Pixel von der Seite entfernt, zu weit draußen für ein Netz. Es wurde nichts exportiert; verschieben Sie die Zeichnung zurück auf die Seite oder wählen Sie ein anderes Bild.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_model.cpp" line="92"/>
        <source>No object of frame %1 can be made 3D: each is a dot or a straight line, with no area to inflate, or lies too far from the page to mesh. Nothing was exported; draw a shape or choose another frame.</source>
        <translation>Kein Objekt von Einzelbild %1 lässt sich in 3D umwandeln: Jedes ist ein Punkt oder eine gerade Linie ohne Fläche zum Aufblasen oder liegt zu weit von der Seite entfernt für ein Netz. Es wurde nichts exportiert; zeichnen Sie eine Form oder wählen Sie ein anderes Bild.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_model.cpp" line="99"/>
        <source>No object of frame %1 can be made 3D: each is a dot or a straight line, with no area to inflate. Nothing was exported; draw a shape or choose another frame.</source>
        <translation>Kein Objekt von Einzelbild %1 lässt sich in 3D umwandeln: Jedes ist ein Punkt oder eine gerade Linie ohne Fläche zum Aufblasen. Es wurde nichts exportiert; zeichnen Sie eine Form oder wählen Sie ein anderes Bild.</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/export/export_model.cpp" line="110"/>
        <source>%n object(s) of frame %1 could not be made 3D (a dot or a straight line has no area to inflate; a drawing far off the page cannot be meshed) and were left out.</source>
        <translation>
            <numerusform>%n Objekt von Einzelbild %1 ließ sich nicht in 3D umwandeln (ein Punkt oder eine gerade Linie hat keine Fläche zum Aufblasen; eine Zeichnung weit außerhalb der Seite lässt sich nicht vernetzen) und wurde weggelassen.</numerusform>
            <numerusform>%n Objekte von Einzelbild %1 ließen sich nicht in 3D umwandeln (ein Punkt oder eine gerade Linie hat keine Fläche zum Aufblasen; eine Zeichnung weit außerhalb der Seite lässt sich nicht vernetzen) und wurden weggelassen.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/export/export_obj.cpp" line="187"/>
        <source>&quot;%1&quot; would be overwritten by its own material file; give a file name ending in .obj.</source>
        <translation>„%1“ würde von seiner eigenen Materialdatei überschrieben; geben Sie einen Dateinamen an, der auf .obj endet.</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/export/export_model.cpp" line="115"/>
        <source>%n object(s) of frame %1 could not be made 3D (a dot or a straight line has no area to inflate) and were left out.</source>
        <translation>
            <numerusform>%n Objekt von Einzelbild %1 ließ sich nicht in 3D umwandeln (ein Punkt oder eine gerade Linie hat keine Fläche zum Aufblasen) und wurde weggelassen.</numerusform>
            <numerusform>%n Objekte von Einzelbild %1 ließen sich nicht in 3D umwandeln (ein Punkt oder eine gerade Linie hat keine Fläche zum Aufblasen) und wurden weggelassen.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/export/export_glb.cpp" line="48"/>
        <source>Frame %1 makes a 3D model larger than a glTF file can hold (4 GiB); export it as OBJ instead.</source>
        <translation>Einzelbild %1 ergibt ein 3D-Modell, das größer ist, als eine glTF-Datei fassen kann (4 GiB); exportieren Sie es stattdessen als OBJ.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_sound.cpp" line="76"/>
        <source>The sound &quot;%1&quot; is left out: %2</source>
        <translation>Der Sound „%1“ wird weggelassen: %2</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_export.cpp" line="18"/>
        <source>The reference &quot;%1&quot; is left out: %2</source>
        <translation>Die Referenz „%1“ wird weggelassen: %2</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_lottie.cpp" line="759"/>
        <source>the zip container failed</source>
        <translation>der ZIP-Container ließ sich nicht schreiben</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_lottie.cpp" line="775"/>
        <source>Lottie has no place for the reference picture; it is left out.</source>
        <translation>Lottie kann das Referenzbild nicht aufnehmen; es wird weggelassen.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_lottie.cpp" line="777"/>
        <source>Lottie carries no sound; the soundtrack is left out.</source>
        <translation>Lottie enthält keinen Ton; die Tonspur wird weggelassen.</translation>
    </message>
</context>
<context>
    <name>ExportDone</name>
    <message>
        <location filename="../ui/src/export/export_done.cpp" line="26"/>
        <source>Export Finished</source>
        <translation>Export abgeschlossen</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_done.cpp" line="31"/>
        <source>Show in Folder</source>
        <translation>Im Ordner zeigen</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_done.cpp" line="38"/>
        <source>Open in Browser</source>
        <translation>Im Browser öffnen</translation>
    </message>
</context>
<context>
    <name>FileMessages</name>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="17"/>
        <source>The file is not there any more: it may have been moved, renamed or deleted.</source>
        <translation>Die Datei ist nicht mehr vorhanden: Sie wurde möglicherweise verschoben, umbenannt oder gelöscht.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="21"/>
        <source>This is a folder, not an animation. Choose a file ending in .finbook.</source>
        <translation>Dies ist ein Ordner, keine Animation. Wählen Sie eine Datei mit der Endung .finbook.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="23"/>
        <source>This is a device or a pipe, not an animation. Choose a file ending in .finbook.</source>
        <translation>Dies ist ein Gerät oder eine Pipe, keine Animation. Wählen Sie eine Datei mit der Endung .finbook.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="26"/>
        <source>You are not allowed to read this file. Ask whoever owns it to share it with you, or open a copy of it.</source>
        <translation>Sie dürfen diese Datei nicht lesen. Bitten Sie die Person, der sie gehört, sie für Sie freizugeben, oder öffnen Sie eine Kopie davon.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="29"/>
        <source>The disk could not read the file. If it is on a removable drive or a network folder, check that it is still connected.</source>
        <translation>Die Datei konnte nicht vom Datenträger gelesen werden. Wenn sie auf einem Wechseldatenträger oder in einem Netzwerkordner liegt, prüfen Sie, ob dieser noch verbunden ist.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="33"/>
        <source>The file is empty: there is no drawing in it.</source>
        <translation>Die Datei ist leer: Sie enthält keine Zeichnung.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="34"/>
        <source>This is not a Finbook animation. Choose a file ending in .finbook.</source>
        <translation>Dies ist keine Finbook-Animation. Wählen Sie eine Datei mit der Endung .finbook.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="37"/>
        <source>It was saved by a newer version of Finbook. Install that version to open it.</source>
        <translation>Sie wurde mit einer neueren Finbook-Version gespeichert. Installieren Sie diese Version, um sie zu öffnen.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="40"/>
        <source>The file is damaged near the end: it looks cut off. Perhaps a copy or a save was interrupted.</source>
        <translation>Die Datei ist gegen Ende beschädigt: Sie scheint abgeschnitten zu sein. Vielleicht wurde ein Kopier- oder Speichervorgang unterbrochen.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="43"/>
        <source>The file is damaged, or too large for this computer: it asks for more memory than Finbook can use.</source>
        <translation>Die Datei ist beschädigt oder zu groß für diesen Computer: Sie benötigt mehr Arbeitsspeicher, als Finbook nutzen kann.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="46"/>
        <source>The file is damaged: some of it changed after it was saved. Finbook can open what is still readable.</source>
        <translation>Die Datei ist beschädigt: Ein Teil davon wurde nach dem Speichern verändert. Finbook kann öffnen, was noch lesbar ist.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="50"/>
        <source>This computer has not enough free memory to open the file. Close other programs or documents and try again.</source>
        <translation>Dieser Computer hat nicht genug freien Arbeitsspeicher, um die Datei zu öffnen. Schließen Sie andere Programme oder Dokumente und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="57"/>
        <source>The file is damaged: part of it cannot be read.</source>
        <translation>Die Datei ist beschädigt: Ein Teil davon kann nicht gelesen werden.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="64"/>
        <source>Finbook cannot open “%1”.</source>
        <translation>Finbook kann „%1“ nicht öffnen.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="68"/>
        <source>Finbook kept the version saved before it as “%1” in the same folder: open that one to get your work back.</source>
        <translation>Finbook hat die zuvor gespeicherte Version als „%1“ im selben Ordner aufbewahrt: Öffnen Sie diese, um Ihre Arbeit wiederherzustellen.</translation>
    </message>
</context>
<context>
    <name>FinbookFile</name>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="30"/>
        <source>layer %1</source>
        <translation>Ebene %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="32"/>
        <source>frame %1</source>
        <translation>Einzelbild %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="35"/>
        <source>, object &quot;%1&quot;</source>
        <translation>, Objekt „%1“</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="36"/>
        <source>, object %1</source>
        <translation>, Objekt %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="38"/>
        <source>, stroke %1</source>
        <translation>, Strich %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="42"/>
        <source>stroke data %1</source>
        <translation>Strichdaten %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="44"/>
        <source>pose %1</source>
        <translation>Pose %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="85"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="65"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="93"/>
        <source>%1 runs past the end of its record (%2 bytes needed, %3 left), so a length in the file is wrong</source>
        <translation>%1 reicht über das Ende seines Eintrags hinaus (%2 Bytes benötigt, %3 übrig), also ist eine Längenangabe in der Datei falsch</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="100"/>
        <source>the file ends inside %1 (%2 bytes needed, %3 left)</source>
        <translation>%1 ist unvollständig, die Datei endet vorzeitig (%2 Bytes benötigt, %3 übrig)</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="116"/>
        <source>%1 claims %2 entries but only %3 bytes remain</source>
        <translation>%1 gibt %2 Einträge an, es sind aber nur noch %3 Bytes übrig</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="142"/>
        <source>%1 has %2 unexpected bytes at its end</source>
        <translation>%1 hat am Ende %2 unerwartete Bytes</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="36"/>
        <source>%1 The file is incomplete (perhaps an interrupted copy or save); if there is a backup with the same name ending in ~, open that instead.</source>
        <translation>%1 Die Datei ist unvollständig (vielleicht wurde ein Kopier- oder Speichervorgang unterbrochen); falls es eine Sicherungskopie mit demselben Namen und angehängtem ~ gibt, öffnen Sie stattdessen diese.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="42"/>
        <source>%1 The file is damaged; if there is a backup with the same name ending in ~, open that instead.</source>
        <translation>%1 Die Datei ist beschädigt; falls es eine Sicherungskopie mit demselben Namen und angehängtem ~ gibt, öffnen Sie stattdessen diese.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="47"/>
        <source>%1 The file is damaged; Finbook can open what is still readable of it, or open the backup with the same name ending in ~ if there is one.</source>
        <translation>%1 Die Datei ist beschädigt; Finbook kann öffnen, was davon noch lesbar ist, oder Sie öffnen die Sicherungskopie mit demselben Namen und angehängtem ~, falls es eine gibt.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="52"/>
        <source>%1 Close other programs or documents and try again.</source>
        <translation>%1 Schließen Sie andere Programme oder Dokumente und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="75"/>
        <source>Could not save &quot;%1&quot;: %2. The previous file is unchanged; free some disk space or choose another folder, then save again.</source>
        <translation>„%1“ konnte nicht gespeichert werden: %2. Die bisherige Datei ist unverändert; geben Sie Speicherplatz frei oder wählen Sie einen anderen Ordner und speichern Sie dann erneut.</translation>
    </message>
    <message>
        <location filename="../model/src/io/atomic_file.cpp" line="249"/>
        <source>the backup &quot;%1&quot; cannot be written (%2)</source>
        <translation>die Sicherungskopie „%1“ kann nicht geschrieben werden (%2)</translation>
    </message>
    <message>
        <location filename="../model/src/io/atomic_file.cpp" line="350"/>
        <source>the disk is full</source>
        <translation>der Datenträger ist voll</translation>
    </message>
    <message>
        <location filename="../model/src/io/atomic_file.cpp" line="352"/>
        <source>the disk is read-only</source>
        <translation>der Datenträger ist schreibgeschützt</translation>
    </message>
    <message>
        <location filename="../model/src/io/atomic_file.cpp" line="354"/>
        <source>you do not have permission to write in the folder &quot;%1&quot;</source>
        <translation>Sie haben keine Schreibberechtigung für den Ordner „%1“</translation>
    </message>
    <message>
        <location filename="../model/src/io/atomic_file.cpp" line="357"/>
        <source>the folder &quot;%1&quot; does not exist</source>
        <translation>der Ordner „%1“ existiert nicht</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="81"/>
        <source>Could not save &quot;%1&quot;: %2. The previous file is unchanged; choose another folder, then save again.</source>
        <translation>„%1“ konnte nicht gespeichert werden: %2. Die bisherige Datei ist unverändert; wählen Sie einen anderen Ordner und speichern Sie dann erneut.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="91"/>
        <source>Cannot open &quot;%1&quot;: %2. Check that the file exists and that you may read it.</source>
        <translation>„%1“ kann nicht geöffnet werden: %2. Prüfen Sie, ob die Datei existiert und ob Sie sie lesen dürfen.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="132"/>
        <source>it is a folder</source>
        <translation>es ist ein Ordner</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="165"/>
        <source>Cannot read &quot;%1&quot;: %2.</source>
        <translation>„%1“ kann nicht gelesen werden: %2.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="146"/>
        <location filename="../model/src/finbook_file_io.cpp" line="176"/>
        <source>Cannot open &quot;%1&quot;. %2</source>
        <translation>„%1“ kann nicht geöffnet werden. %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="136"/>
        <source>Cannot open &quot;%1&quot;: it is a device, a pipe or a socket, not a file. Choose a .finbook file.</source>
        <translation>„%1“ kann nicht geöffnet werden: Es ist ein Gerät, eine Pipe oder ein Socket, keine Datei. Wählen Sie eine .finbook-Datei.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="155"/>
        <source>Cannot open &quot;%1&quot;: there is not enough memory for its %2 MB. Close other programs or documents and try again.</source>
        <translation>„%1“ kann nicht geöffnet werden: Für die %2 MB der Datei ist nicht genug Arbeitsspeicher vorhanden. Schließen Sie andere Programme oder Dokumente und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="266"/>
        <source>Could not save &quot;%1&quot;: the drawing holds invalid data (%2). The previous file is unchanged.</source>
        <translation>„%1“ konnte nicht gespeichert werden: Die Zeichnung enthält ungültige Daten (%2). Die bisherige Datei ist unverändert.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="44"/>
        <source>unknown %1 %2</source>
        <translation>unbekannter %1 %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="47"/>
        <source>it holds data (&quot;%1&quot;) that this version of Finbook does not know, so it was probably made by a newer Finbook; please update Finbook to open it</source>
        <translation>die Datei enthält Daten („%1“), die diese Finbook-Version nicht kennt, und wurde daher wohl mit einer neueren Finbook-Version erstellt; bitte aktualisieren Sie Finbook, um sie zu öffnen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="67"/>
        <source>more problems were found and repaired the same way</source>
        <translation>weitere Probleme wurden gefunden und auf dieselbe Weise behoben</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="76"/>
        <source>it describes more than a file of its size can hold (opening it would take more than %1 MB of memory)</source>
        <translation>die Datei beschreibt mehr, als eine Datei ihrer Größe enthalten kann (zum Öffnen wären mehr als %1 MB Arbeitsspeicher nötig)</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="45"/>
        <source>its format version %1 is not one any Finbook writes (this version reads %2 to %3), so the version number is damaged</source>
        <translation>ihre Formatversion %1 schreibt kein Finbook (diese Version liest %2 bis %3), also ist die Versionsnummer beschädigt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="55"/>
        <source>the file is empty</source>
        <translation>die Datei ist leer</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="57"/>
        <source>the file header</source>
        <translation>der Dateikopf</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="59"/>
        <source>it is not a Finbook animation</source>
        <translation>die Datei ist keine Finbook-Animation</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="61"/>
        <source>the file ends inside its header</source>
        <translation>die Datei endet mitten im Dateikopf</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="62"/>
        <source>the format version</source>
        <translation>die Formatversion</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="67"/>
        <source>it was made by a newer version of Finbook (file format %1; this version reads up to %2); please update Finbook to open it</source>
        <translation>die Datei wurde mit einer neueren Finbook-Version erstellt (Dateiformat %1; diese Version liest bis %2); bitte aktualisieren Sie Finbook, um sie zu öffnen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="113"/>
        <source>the file&apos;s section list</source>
        <translation>die Abschnittsliste der Datei</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="116"/>
        <source>the file ends before its end</source>
        <translation>die Datei endet vorzeitig</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="120"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="121"/>
        <source>a section header</source>
        <translation>ein Abschnittskopf</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="122"/>
        <source>section %1</source>
        <translation>Abschnitt %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="141"/>
        <source>the file&apos;s end is damaged</source>
        <translation>das Ende der Datei ist beschädigt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="146"/>
        <source>its length (%1 bytes) runs past the end of the file (%2 bytes left), yet the file ends with its end marker, so the length is damaged</source>
        <translation>ihre Länge (%1 Bytes) reicht über das Dateiende hinaus (%2 Bytes übrig), obwohl die Datei mit ihrer Endmarke endet; die Längenangabe ist also beschädigt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="154"/>
        <source>the file ends inside this section (%1 bytes announced, %2 left)</source>
        <translation>die Datei endet mitten in diesem Abschnitt (%1 Bytes angekündigt, %2 übrig)</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="158"/>
        <source>the file ends inside this section; what it holds is read</source>
        <translation>die Datei endet mitten in diesem Abschnitt; sein vorhandener Inhalt wird gelesen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="162"/>
        <source>a section</source>
        <translation>ein Abschnitt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="166"/>
        <source>the file ends before this section&apos;s checksum</source>
        <translation>die Datei endet vor der Prüfsumme dieses Abschnitts</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="168"/>
        <source>a section checksum</source>
        <translation>eine Abschnittsprüfsumme</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="171"/>
        <source>its checksum does not match, so its bytes changed after it was saved</source>
        <translation>seine Prüfsumme stimmt nicht, seine Bytes wurden also nach dem Speichern verändert</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="178"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="281"/>
        <source>section %1 is missing</source>
        <translation>Abschnitt %1 fehlt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="180"/>
        <source>the end marker</source>
        <translation>die Endmarke</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="181"/>
        <source>the file</source>
        <translation>die Datei</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="217"/>
        <source>a sound clip comes before the frames</source>
        <translation>ein Tonclip steht vor den Bildern</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="224"/>
        <source>the layers come before the frames</source>
        <translation>die Ebenen stehen vor den Einzelbildern</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="226"/>
        <source>the layers are repeated</source>
        <translation>die Ebenen kommen doppelt vor</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="235"/>
        <source>the pictures come before the frames</source>
        <translation>die Bilder stehen vor den Einzelbildern</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="237"/>
        <source>the pictures are repeated</source>
        <translation>die Bilder kommen doppelt vor</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="246"/>
        <source>the camera comes before the frames</source>
        <translation>die Kamera steht vor den Bildern</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="248"/>
        <source>the camera is repeated</source>
        <translation>die Kamera kommt mehrfach vor</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="257"/>
        <source>the swap sets come before the frames</source>
        <translation>die Austauschsätze stehen vor den Bildern</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="259"/>
        <source>the swap sets are repeated</source>
        <translation>die Austauschsätze sind wiederholt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="267"/>
        <source>an unknown section is left out</source>
        <translation>ein unbekannter Abschnitt wird ausgelassen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="269"/>
        <source>section</source>
        <translation>Abschnitt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="276"/>
        <source>the section is repeated or out of order</source>
        <translation>der Abschnitt ist doppelt vorhanden oder steht an der falschen Stelle</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="290"/>
        <source>the palette</source>
        <translation>die Palette</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="318"/>
        <source>the end of the section could not be read</source>
        <translation>das Ende des Abschnitts konnte nicht gelesen werden</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="319"/>
        <source>the section</source>
        <translation>der Abschnitt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="329"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="391"/>
        <source>the document settings</source>
        <translation>die Dokumenteinstellungen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="332"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="333"/>
        <source>the canvas size</source>
        <translation>die Leinwandgröße</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="337"/>
        <source>the canvas size %1×%2 is outside 1 to %3 pixels</source>
        <translation>die Leinwandgröße %1×%2 liegt nicht zwischen 1 und %3 Pixeln</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="343"/>
        <source>the background colour</source>
        <translation>die Hintergrundfarbe</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="344"/>
        <source>the frame rate</source>
        <translation>die Bildrate</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="348"/>
        <source>the frame rate %1 is outside %2 to %3</source>
        <translation>die Bildrate %1 liegt nicht zwischen %2 und %3</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="354"/>
        <source>the loop flag</source>
        <translation>die Endlosschleifen-Angabe</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="357"/>
        <source>the loop flag %1 is neither 0 nor 1</source>
        <translation>die Endlosschleifen-Angabe %1 ist weder 0 noch 1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="359"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="360"/>
        <source>the play range</source>
        <translation>der Wiedergabebereich</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="364"/>
        <source>the play range %1 to %2 is invalid</source>
        <translation>der Wiedergabebereich %1 bis %2 ist ungültig</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="368"/>
        <source>the next id</source>
        <translation>die nächste ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="370"/>
        <source>the close-gap setting</source>
        <translation>die Einstellung zum Lückenschließen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="373"/>
        <source>the close-gap setting %1 is outside 0 to %2 pixels</source>
        <translation>die Einstellung zum Lückenschließen %1 liegt nicht zwischen 0 und %2 Pixeln</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="382"/>
        <source>the next free id %1 is larger than any id can be</source>
        <translation>die nächste freie ID %1 ist größer als jede mögliche ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="421"/>
        <source>its parts are joined in a way too costly to work out</source>
        <translation>ihre Teile sind so verbunden, dass das Auflösen der Verbindungen zu aufwendig wäre</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="58"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="60"/>
        <source>the frame list</source>
        <translation>die Einzelbildliste</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="68"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="74"/>
        <source>a frame</source>
        <translation>ein Einzelbild</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="71"/>
        <source>the frame is cut off and is left out, with any after it</source>
        <translation>das Einzelbild ist abgeschnitten und wird samt allen folgenden ausgelassen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="80"/>
        <source>%1; the frame is left out</source>
        <translation>%1; das Einzelbild wird ausgelassen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="89"/>
        <source>a frame id</source>
        <translation>eine Einzelbild-ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="90"/>
        <source>the frame</source>
        <translation>das Einzelbild</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="91"/>
        <source>a frame hold</source>
        <translation>eine Haltedauer</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="95"/>
        <source>the hold %1 is outside 1 to %2</source>
        <translation>die Haltedauer %1 liegt nicht zwischen 1 und %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="97"/>
        <source>the object list</source>
        <translation>die Objektliste</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="104"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="110"/>
        <source>an object</source>
        <translation>ein Objekt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="107"/>
        <source>the object is cut off and is left out, with any after it</source>
        <translation>das Objekt ist abgeschnitten und wird samt allen folgenden ausgelassen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="116"/>
        <source>%1; the object is left out</source>
        <translation>%1; das Objekt wird ausgelassen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="121"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="122"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="212"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="213"/>
        <source>a chunk header</source>
        <translation>ein Blockkopf</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="123"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="214"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="232"/>
        <source>a chunk</source>
        <translation>ein Block</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="124"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="222"/>
        <source>chunk</source>
        <translation>Block</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="132"/>
        <source>an object id</source>
        <translation>eine Objekt-ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="133"/>
        <source>the object</source>
        <translation>das Objekt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="134"/>
        <source>the object flags</source>
        <translation>die Objektattribute</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="137"/>
        <source>the object flags 0x%1 are unknown</source>
        <translation>die Objektattribute 0x%1 sind unbekannt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="140"/>
        <source>the mesh density</source>
        <translation>die Netzdichte</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="143"/>
        <source>the mesh density %1 is not a number from 0 to 1000</source>
        <translation>die Netzdichte %1 ist keine Zahl von 0 bis 1000</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="160"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="166"/>
        <source>the object name</source>
        <translation>der Objektname</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="163"/>
        <source>the object name is %1 bytes long (at most %2)</source>
        <translation>der Objektname ist %1 Bytes lang (höchstens %2)</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="174"/>
        <source>the object name is not valid UTF-8 text</source>
        <translation>der Objektname ist kein gültiger UTF-8-Text</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="181"/>
        <source>the stroke list</source>
        <translation>die Strichliste</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="188"/>
        <source>a stroke id</source>
        <translation>eine Strich-ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="199"/>
        <source>the stroke</source>
        <translation>der Strich</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="341"/>
        <source>its pose has %n stroke(s) but the object has %1</source>
        <translation>
            <numerusform>seine Pose hat %n Strich, das Objekt aber %1</numerusform>
            <numerusform>seine Pose hat %n Striche, das Objekt aber %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="348"/>
        <source>stroke %1 has %n point(s) but its pose has %2</source>
        <translation>
            <numerusform>Strich %1 hat %n Punkt, seine Pose aber %2</numerusform>
            <numerusform>Strich %1 hat %n Punkte, seine Pose aber %2</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="189"/>
        <source>a stroke reference</source>
        <translation>ein Strichverweis</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="49"/>
        <source>%1 claims %2 entries; the %3 that fit are read</source>
        <translation>%1 gibt %2 Einträge an; die %3, die hineinpassen, werden gelesen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="192"/>
        <source>it refers to stroke data %1 of %2</source>
        <translation>er verweist auf Strichdaten %1 von %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="220"/>
        <source>an unknown chunk is left out</source>
        <translation>ein unbekannter Block wird ausgelassen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="227"/>
        <source>chunk %1 appears twice or with another rig</source>
        <translation>Block %1 kommt doppelt oder mit einem anderen Rig vor</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="236"/>
        <source>%1; the chunk is left out</source>
        <translation>%1; der Block wird ausgelassen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="264"/>
        <source>the skeleton&apos;s join</source>
        <translation>die Verbindung des Skeletts</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="266"/>
        <source>a join comes without a skeleton</source>
        <translation>eine Verbindung steht ohne Skelett</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="274"/>
        <source>the skeleton&apos;s join is damaged</source>
        <translation>die Verbindung des Skeletts ist beschädigt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="287"/>
        <source>the pin list</source>
        <translation>die Pin-Liste</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="292"/>
        <source>a pin id</source>
        <translation>eine Pin-ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="293"/>
        <source>pin %1</source>
        <translation>Pin %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="296"/>
        <source>a pin position</source>
        <translation>eine Pin-Position</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="299"/>
        <source>pin %1 has a non-finite position</source>
        <translation>Pin %1 hat eine nicht endliche Position</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="310"/>
        <source>the cage corner list</source>
        <translation>die Käfigeckenliste</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="312"/>
        <source>the cage has fewer than 3 corners</source>
        <translation>der Käfig hat weniger als 3 Ecken</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="319"/>
        <source>a cage corner</source>
        <translation>eine Käfigecke</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="322"/>
        <source>cage corner %1 has a non-finite position</source>
        <translation>Käfigecke %1 hat eine nicht endliche Position</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="331"/>
        <source>a pose reference</source>
        <translation>ein Posenverweis</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="333"/>
        <source>its pose refers to pose %1 of %2</source>
        <translation>seine Pose verweist auf Pose %1 von %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="337"/>
        <source>its pose: %1</source>
        <translation>seine Pose: %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="360"/>
        <source>%1 has no id</source>
        <translation>%1 hat keine ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="361"/>
        <source>%1 has the id %2, larger than any id can be</source>
        <translation>%1 hat die ID %2, die größer ist als jede mögliche ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="369"/>
        <source>%1 has the id %2, which is already used</source>
        <translation>%1 hat die ID %2, die bereits vergeben ist</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="449"/>
        <source>the next free id %1 is not above the largest id %2</source>
        <translation>die nächste freie ID %1 ist nicht größer als die größte ID %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="467"/>
        <source>the id %1 is used twice</source>
        <translation>die ID %1 wird doppelt verwendet</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="472"/>
        <source>no frame of it could be read; there is nothing to recover</source>
        <translation>kein einziges Einzelbild konnte gelesen werden; es gibt nichts wiederherzustellen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="481"/>
        <source>there is not enough memory to open this file</source>
        <translation>es ist nicht genug Arbeitsspeicher vorhanden, um diese Datei zu öffnen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="26"/>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="28"/>
        <source>a stroke</source>
        <translation>ein Strich</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="32"/>
        <source>point %1 has a non-finite coordinate</source>
        <translation>Punkt %1 hat eine nicht endliche Koordinate</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="48"/>
        <source>%n point(s) with a non-finite coordinate are left out</source>
        <translation>
            <numerusform>%n Punkt mit einer nicht endlichen Koordinate wird ausgelassen</numerusform>
            <numerusform>%n Punkte mit einer nicht endlichen Koordinate werden ausgelassen</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="57"/>
        <source>the stroke table</source>
        <translation>die Strichtabelle</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="71"/>
        <source>a stroke colour</source>
        <translation>eine Strichfarbe</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="72"/>
        <source>a stroke width</source>
        <translation>eine Strichbreite</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="74"/>
        <source>the width %1 is not a number above 0 and up to %2</source>
        <translation>die Breite %1 ist keine Zahl größer als 0 und höchstens %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="90"/>
        <source>the pose table</source>
        <translation>die Posentabelle</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="97"/>
        <source>a pose</source>
        <translation>eine Pose</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="24"/>
        <source>the skeleton</source>
        <translation>das Skelett</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="27"/>
        <source>its skeleton has no joints</source>
        <translation>sein Skelett hat keine Gelenke</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="34"/>
        <source>skeleton joint %1 has a non-finite value</source>
        <translation>Skelettgelenk %1 hat einen nicht endlichen Wert</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="41"/>
        <source>skeleton joint %1 has a negative radius</source>
        <translation>Skelettgelenk %1 hat einen negativen Radius</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="45"/>
        <source>skeleton joint %1 has an invalid parent</source>
        <translation>Skelettgelenk %1 hat ein ungültiges Elterngelenk</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="50"/>
        <source>the skeleton&apos;s root is not a root joint</source>
        <translation>die Wurzel des Skeletts ist kein Wurzelgelenk</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="51"/>
        <source>the skeleton&apos;s pose has a non-finite value</source>
        <translation>die Pose des Skeletts hat einen nicht endlichen Wert</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="54"/>
        <source>a skeleton setting is outside 0 to 1</source>
        <translation>eine Skeletteinstellung liegt nicht zwischen 0 und 1</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="64"/>
        <source>the skeleton has an unknown skinning mode</source>
        <translation>das Skelett hat einen unbekannten Skinning-Modus</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="73"/>
        <source>skeleton joint %1 has an unknown lock state</source>
        <translation>Skelettgelenk %1 hat einen unbekannten Sperrzustand</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="84"/>
        <source>the skeleton&apos;s limb bases</source>
        <translation>die Gliedmaßenansätze des Skeletts</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="87"/>
        <source>limb bases come without a skeleton</source>
        <translation>Gliedmaßenansätze stehen ohne Skelett</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="90"/>
        <source>the skeleton has %1 joints but %2 limb base flags</source>
        <translation>das Skelett hat %1 Gelenke, aber %2 Markierungen für Gliedmaßenansätze</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="99"/>
        <source>skeleton joint %1 has an unknown limb base flag</source>
        <translation>Skelettgelenk %1 hat eine unbekannte Markierung für den Gliedmaßenansatz</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_recover.cpp" line="51"/>
        <source>%1 damaged bytes could not be read; reading goes on with section %2</source>
        <translation>%1 beschädigte Bytes konnten nicht gelesen werden; das Lesen wird mit Abschnitt %2 fortgesetzt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_recover.cpp" line="59"/>
        <source>the last %1 bytes of the file are damaged and could not be read</source>
        <translation>die letzten %1 Bytes der Datei sind beschädigt und konnten nicht gelesen werden</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/finbook_file_recover.cpp" line="139"/>
        <source>%n missing or repeated id(s) were replaced by new ones</source>
        <translation>
            <numerusform>%n fehlende oder doppelte ID wurde durch eine neue ersetzt</numerusform>
            <numerusform>%n fehlende oder doppelte IDs wurden durch neue ersetzt</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/recovery/autosaver.cpp" line="162"/>
        <source>Autosave could not write a recovery copy: %1.</source>
        <translation>Die automatische Sicherung konnte keine Wiederherstellungskopie schreiben: %1.</translation>
    </message>
    <message>
        <location filename="../model/src/recovery/recovery_writer.h" line="43"/>
        <source>there is not enough memory</source>
        <translation>es ist nicht genug Arbeitsspeicher vorhanden</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="49"/>
        <source>the fill list</source>
        <translation>die Liste der Füllungen</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="52"/>
        <source>the object claims %1 fills, more than %2</source>
        <translation>das Objekt gibt %1 Füllungen an, mehr als %2</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="42"/>
        <source>a fill&apos;s seed is not a number</source>
        <translation>der Startpunkt einer Füllung ist keine Zahl</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="27"/>
        <source>a fill names the stroke id %1, which no stroke can have</source>
        <translation>eine Füllung nennt die Strich-ID %1, die kein Strich haben kann</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="33"/>
        <source>a fill&apos;s stroke ids are not in order</source>
        <translation>die Strich-IDs einer Füllung sind nicht geordnet</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="69"/>
        <source>the fill regions</source>
        <translation>die Füllbereiche</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="72"/>
        <source>the object gives regions of %1 fills but has %2</source>
        <translation>das Objekt gibt Bereiche für %1 Füllungen an, hat aber %2</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="82"/>
        <source>the object&apos;s fills claim more than %1 regions</source>
        <translation>die Füllungen des Objekts beanspruchen mehr als %1 Bereiche</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="48"/>
        <location filename="../model/src/reference/reference_section.cpp" line="50"/>
        <source>the reference layer</source>
        <translation>die Referenzebene</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="52"/>
        <source>the section is repeated</source>
        <translation>der Abschnitt kommt doppelt vor</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="57"/>
        <source>the reference is of an unknown kind (%1)</source>
        <translation>die Referenz ist von unbekannter Art (%1)</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="61"/>
        <source>the reference has unknown flags</source>
        <translation>die Referenz hat unbekannte Kennzeichen</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="76"/>
        <source>the reference&apos;s place, scale, rotation, opacity or rate is not a number or out of range</source>
        <translation>Lage, Maßstab, Drehung, Deckkraft oder Rate der Referenz ist keine Zahl oder außerhalb des Bereichs</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="80"/>
        <source>the reference&apos;s name is too long</source>
        <translation>der Name der Referenz ist zu lang</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="86"/>
        <source>the reference claims %1 bytes but only %2 remain</source>
        <translation>die Referenz gibt %1 Bytes an, es bleiben aber nur %2</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="99"/>
        <source>the reference layer is left out: %1</source>
        <translation>die Referenzebene wird weggelassen: %1</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="106"/>
        <location filename="../model/src/reference/reference_section.cpp" line="108"/>
        <source>the reference&apos;s picture sequence</source>
        <translation>die Bildfolge der Referenz</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="112"/>
        <source>it does not follow a reference picture, or is repeated</source>
        <translation>er folgt keinem Referenzbild oder ist wiederholt</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="115"/>
        <source>it claims %1 pictures</source>
        <translation>er gibt %1 Bilder an</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="123"/>
        <source>picture %1 claims %2 bytes but only %3 remain</source>
        <translation>Bild %1 gibt %2 Bytes an, aber nur %3 sind übrig</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="142"/>
        <source>the reference&apos;s further pictures are left out: %1</source>
        <translation>die weiteren Bilder der Referenz werden weggelassen: %1</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="17"/>
        <source>sound clip %1</source>
        <translation>Tonclip %1</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="20"/>
        <location filename="../model/src/sound/sound_section.cpp" line="34"/>
        <location filename="../model/src/sound/sound_section.cpp" line="79"/>
        <source>the sound clip</source>
        <translation>der Tonclip</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="24"/>
        <source>%1; the sound clip is left out</source>
        <translation>%1; der Tonclip wird weggelassen</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="32"/>
        <source>the file holds more than %1 sound clips</source>
        <translation>die Datei enthält mehr als %1 Tonclips</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="39"/>
        <source>the sound starts at %1, outside 0 to %2</source>
        <translation>der Ton beginnt bei %1, außerhalb von 0 bis %2</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="46"/>
        <source>the sound&apos;s volume %1 is outside 0 to %2</source>
        <translation>die Lautstärke %1 des Tons liegt außerhalb von 0 bis %2</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="54"/>
        <source>the sound flags 0x%1 are unknown</source>
        <translation>die Ton-Flags 0x%1 sind unbekannt</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="58"/>
        <source>the sound&apos;s name is %1 bytes long (at most %2)</source>
        <translation>der Name des Tons ist %1 Byte lang (höchstens %2)</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="68"/>
        <source>the sound&apos;s name is not valid UTF-8 text</source>
        <translation>der Name des Tons ist kein gültiger UTF-8-Text</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="72"/>
        <source>the sound is %1 MB long (at most %2 MB)</source>
        <translation>der Ton ist %1 MB groß (höchstens %2 MB)</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="76"/>
        <source>the sound clip holds no sound</source>
        <translation>der Tonclip enthält keinen Ton</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_chunk.cpp" line="11"/>
        <source>the fill shading list</source>
        <translation>die Liste der Füllungsschattierungen</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_chunk.cpp" line="15"/>
        <source>the object shades %1 fills but has %2</source>
        <translation>das Objekt schattiert %1 Füllungen, hat aber %2</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_chunk.cpp" line="22"/>
        <source>a fill&apos;s shading (%1, %2) is not one Finbook knows</source>
        <translation>die Schattierung einer Füllung (%1, %2) kennt Finbook nicht</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_chunk.cpp" line="34"/>
        <source>the light</source>
        <translation>das Licht</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_chunk.cpp" line="40"/>
        <source>the light&apos;s direction (%1°, %2°) is outside 0 to 360° and 0 to 90°</source>
        <translation>die Richtung des Lichts (%1°, %2°) liegt außerhalb von 0 bis 360° und 0 bis 90°</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_section.cpp" line="13"/>
        <location filename="../model/src/camera/camera_section.cpp" line="15"/>
        <source>the camera</source>
        <translation>die Kamera</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_section.cpp" line="20"/>
        <source>the camera has %1 keys (at most %2)</source>
        <translation>die Kamera hat %1 Schlüsselbilder (höchstens %2)</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_section.cpp" line="40"/>
        <source>camera key %1 holds a value out of range; it is left out</source>
        <translation>Kamera-Schlüsselbild %1 enthält einen Wert außerhalb des Bereichs; es wird weggelassen</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_section.cpp" line="46"/>
        <source>camera key %1 is not after the key before it; it is left out</source>
        <translation>Kamera-Schlüsselbild %1 liegt nicht nach dem vorigen; es wird weggelassen</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_section.cpp" line="59"/>
        <source>%1; the camera is left out</source>
        <translation>%1; die Kamera wird weggelassen</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="14"/>
        <location filename="../model/src/scene/layer_section.cpp" line="16"/>
        <source>the layers</source>
        <translation>die Ebenen</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="20"/>
        <source>the file has %1 layers (1 to %2)</source>
        <translation>die Datei hat %1 Ebenen (1 bis %2)</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="28"/>
        <source>the layer</source>
        <translation>die Ebene</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="39"/>
        <source>its opacity is not between 0 and 1</source>
        <translation>ihre Deckkraft liegt nicht zwischen 0 und 1</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="44"/>
        <source>its depth is not between %1 and %2</source>
        <translation>ihre Tiefe liegt nicht zwischen %1 und %2</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="59"/>
        <source>the layers hold %1 frames, but the file has %2</source>
        <translation>die Ebenen enthalten %1 Einzelbilder, die Datei aber %2</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="76"/>
        <source>%1; every frame is put on one layer</source>
        <translation>%1; alle Einzelbilder kommen auf eine Ebene</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="14"/>
        <location filename="../model/src/swap/swap_section.cpp" line="16"/>
        <location filename="../model/src/swap/swap_section.cpp" line="52"/>
        <source>the swap sets</source>
        <translation>die Austauschsätze</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="21"/>
        <source>the file has %1 swap sets (at most %2)</source>
        <translation>die Datei hat %1 Austauschsätze (höchstens %2)</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="28"/>
        <source>swap set %1</source>
        <translation>Austauschsatz %1</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="33"/>
        <source>swap set %1 has %2 drawings (1 to %3)</source>
        <translation>Austauschsatz %1 hat %2 Zeichnungen (1 bis %3)</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="44"/>
        <source>a drawing of swap set %1 carries a pose</source>
        <translation>eine Zeichnung von Austauschsatz %1 trägt eine Pose</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="65"/>
        <source>object %1 shows a drawing the swap sets do not hold</source>
        <translation>Objekt %1 zeigt eine Zeichnung, die in keinem Austauschsatz steht</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="83"/>
        <source>the swap sets link objects the frames do not hold</source>
        <translation>die Austauschsätze verweisen auf Objekte, die in keinem Bild stehen</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="95"/>
        <source>a frame shows a swap set on two objects</source>
        <translation>ein Bild zeigt einen Austauschsatz auf zwei Objekten</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="113"/>
        <source>%1; the swap sets are left out</source>
        <translation>%1; die Austauschsätze werden weggelassen</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="106"/>
        <location filename="../model/src/picture/picture_section.cpp" line="107"/>
        <location filename="../model/src/picture/picture_section.cpp" line="251"/>
        <source>the pictures</source>
        <translation>die Bilder</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="118"/>
        <source>picture %1 is cut off</source>
        <translation>Bild %1 ist abgeschnitten</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="124"/>
        <source>picture %1&apos;s mesh has %2 vertices</source>
        <translation>das Netz von Bild %1 hat %2 Ecken</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="133"/>
        <source>picture %1&apos;s mesh has a vertex outside the picture</source>
        <translation>das Netz von Bild %1 hat eine Ecke außerhalb des Bildes</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="140"/>
        <source>picture %1&apos;s mesh has no triangles</source>
        <translation>das Netz von Bild %1 hat keine Dreiecke</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="148"/>
        <source>picture %1&apos;s mesh names a vertex it does not have</source>
        <translation>das Netz von Bild %1 nennt eine Ecke, die es nicht hat</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="157"/>
        <source>picture %1&apos;s mesh has a triangle turned over or without area</source>
        <translation>das Netz von Bild %1 hat ein umgeklapptes Dreieck oder eines ohne Fläche</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="167"/>
        <source>picture %1 is %2 × %3 pixels: %4</source>
        <translation>Bild %1 ist %2 × %3 Pixel groß: %4</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="181"/>
        <location filename="../model/src/picture/picture_section.cpp" line="191"/>
        <source>picture %1 does not decode: %2</source>
        <translation>Bild %1 lässt sich nicht dekodieren: %2</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="196"/>
        <source>picture %1 is %2 × %3 pixels, not the %4 × %5 it claims</source>
        <translation>Bild %1 ist %2 × %3 Pixel groß, nicht %4 × %5 wie angegeben</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="208"/>
        <source>%1; the objects showing it are left without it</source>
        <translation>%1; die Objekte, die es zeigen, bleiben ohne Bild</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="220"/>
        <source>the object&apos;s picture</source>
        <translation>das Bild des Objekts</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="228"/>
        <source>the picture&apos;s place is out of range</source>
        <translation>die Lage des Bildes liegt außerhalb des gültigen Bereichs</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="236"/>
        <source>the picture&apos;s pose has a point out of range</source>
        <translation>die Pose des Bildes hat einen Punkt außerhalb des gültigen Bereichs</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="259"/>
        <source>an object shows picture %1, which the file does not hold</source>
        <translation>ein Objekt zeigt Bild %1, das die Datei nicht enthält</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="284"/>
        <source>a picture&apos;s pose does not fit its mesh; it is shown at rest</source>
        <translation>die Pose eines Bildes passt nicht zu seinem Netz; es wird in Ruhe gezeigt</translation>
    </message>
</context>
<context>
    <name>MeshImport</name>
    <message>
        <location filename="../model/src/import/mesh_import.cpp" line="22"/>
        <source>Cannot import &quot;%1&quot;: %2</source>
        <translation>„%1“ kann nicht importiert werden: %2</translation>
    </message>
    <message>
        <location filename="../model/src/import/mesh_import.cpp" line="27"/>
        <source>Cannot import &quot;%1&quot;: the mesh has no boundary to draw.</source>
        <translation>„%1“ kann nicht importiert werden: Das Netz hat keinen Rand, der sich zeichnen ließe.</translation>
    </message>
</context>
<context>
    <name>ObjectListModel</name>
    <message numerus="yes">
        <location filename="../model/src/object_list_model.cpp" line="170"/>
        <source>%1: %n stroke(s)</source>
        <translation>
            <numerusform>%1: %n Strich</numerusform>
            <numerusform>%1: %n Striche</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>Palette</name>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="47"/>
        <source>Finbook</source>
        <translation>Finbook</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="48"/>
        <source>Black</source>
        <translation>Schwarz</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="48"/>
        <source>Grey</source>
        <translation>Grau</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="49"/>
        <source>White</source>
        <translation>Weiß</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="49"/>
        <source>Purple</source>
        <translation>Violett</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="50"/>
        <source>Blue</source>
        <translation>Blau</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="50"/>
        <source>Red</source>
        <translation>Rot</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="51"/>
        <source>Orange</source>
        <translation>Orange</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="51"/>
        <source>Yellow</source>
        <translation>Gelb</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="52"/>
        <source>Green</source>
        <translation>Grün</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="52"/>
        <source>Brown</source>
        <translation>Braun</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="75"/>
        <source>it is not a GIMP palette (its first line is not &quot;GIMP Palette&quot;)</source>
        <translation>es ist keine GIMP-Palette (die erste Zeile lautet nicht &quot;GIMP Palette&quot;)</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="97"/>
        <source>line %1: channels &quot;%2&quot; are not RGB or RGBA</source>
        <translation>Zeile %1: die Kanäle &quot;%2&quot; sind weder RGB noch RGBA</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="117"/>
        <source>line %1 is not a colour (%2 numbers from 0 to 255, then a name)</source>
        <translation>Zeile %1 ist keine Farbe (%2 Zahlen von 0 bis 255, dann ein Name)</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="124"/>
        <source>it holds more than %1 colours</source>
        <translation>sie enthält mehr als %1 Farben</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="176"/>
        <source>the palette is damaged</source>
        <translation>die Palette ist beschädigt</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="182"/>
        <source>the palette claims %1 colours</source>
        <translation>die Palette gibt %1 Farben an</translation>
    </message>
</context>
<context>
    <name>PictureImport</name>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="126"/>
        <source>Its stack.xml does not describe an OpenRaster image.</source>
        <translation>Ihre stack.xml beschreibt kein OpenRaster-Bild.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="136"/>
        <source>Its stack.xml gives a layer an invalid position or opacity.</source>
        <translation>Ihre stack.xml gibt einer Ebene eine ungültige Lage oder Deckkraft.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="142"/>
        <source>Its layer groups are nested too deeply.</source>
        <translation>Ihre Ebenengruppen sind zu tief verschachtelt.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="148"/>
        <source>Its stack.xml names a layer without a picture.</source>
        <translation>Ihre stack.xml nennt eine Ebene ohne Bild.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="152"/>
        <source>It has more than %1 layers.</source>
        <translation>Sie hat mehr als %1 Ebenen.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="159"/>
        <source>Its stack.xml is malformed (line %1: %2).</source>
        <translation>Ihre stack.xml ist fehlerhaft (Zeile %1: %2).</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="164"/>
        <source>Its stack.xml is empty.</source>
        <translation>Ihre stack.xml ist leer.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="167"/>
        <source>Its stack of layers is empty.</source>
        <translation>Ihr Ebenenstapel ist leer.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="177"/>
        <source>The picture of its layer “%1” (%2) is missing.</source>
        <translation>Das Bild ihrer Ebene „%1“ (%2) fehlt.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="182"/>
        <source>The picture of its layer “%1” is larger than %2 MB.</source>
        <translation>Das Bild ihrer Ebene „%1“ ist größer als %2 MB.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="187"/>
        <source>The picture of its layer “%1” is damaged or cut short in the file.</source>
        <translation>Das Bild ihrer Ebene „%1“ ist in der Datei beschädigt oder abgeschnitten.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="196"/>
        <source>Its layer “%1”: %2</source>
        <translation>Ihre Ebene „%1“: %2</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="216"/>
        <source>It is a zip archive, but not an OpenRaster picture.</source>
        <translation>Sie ist ein ZIP-Archiv, aber kein OpenRaster-Bild.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="237"/>
        <source>It is not a zip archive, or it is damaged or cut short.</source>
        <translation>Sie ist kein ZIP-Archiv, oder sie ist beschädigt oder unvollständig.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="244"/>
        <source>It has no stack.xml: it is not an OpenRaster picture.</source>
        <translation>Sie hat keine stack.xml: Sie ist kein OpenRaster-Bild.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="248"/>
        <source>Its stack.xml is larger than %1 MB.</source>
        <translation>Ihre stack.xml ist größer als %1 MB.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="252"/>
        <source>Its stack.xml is damaged or cut short.</source>
        <translation>Ihre stack.xml ist beschädigt oder unvollständig.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="272"/>
        <source>It has no visible layer.</source>
        <translation>Sie hat keine sichtbare Ebene.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="23"/>
        <source>“%1” cannot be imported: %2</source>
        <translation>„%1“ kann nicht importiert werden: %2</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="30"/>
        <source>Its picture has no size.</source>
        <translation>Ihr Bild hat keine Größe.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="32"/>
        <source>It claims to be %1 × %2 pixels; a picture may be at most %3 pixels wide and high.</source>
        <translation>Sie gibt %1 × %2 Pixel an; ein Bild darf höchstens %3 Pixel breit und hoch sein.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="40"/>
        <source>It claims to be %1 × %2 pixels; a picture may have at most %3 megapixels.</source>
        <translation>Sie gibt %1 × %2 Pixel an; ein Bild darf höchstens %3 Megapixel haben.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="47"/>
        <source>Its pictures together would take more than %1 MB of memory.</source>
        <translation>Ihre Bilder würden zusammen mehr als %1 MB Speicher belegen.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="72"/>
        <source>Its picture is cut short (the file is incomplete).</source>
        <translation>Ihr Bild ist abgeschnitten (die Datei ist unvollständig).</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="83"/>
        <source>Its picture cannot be decoded: the file is damaged, cut short or too large.</source>
        <translation>Ihr Bild lässt sich nicht dekodieren: Die Datei ist beschädigt, unvollständig oder zu groß.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="94"/>
        <location filename="../model/src/picture/picture_import.cpp" line="36"/>
        <source>It is empty.</source>
        <translation>Sie ist leer.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="102"/>
        <source>It holds a picture of a kind Finbook cannot read.</source>
        <translation>Sie enthält ein Bild einer Art, die Finbook nicht lesen kann.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="111"/>
        <source>Its picture cannot be decoded.</source>
        <translation>Ihr Bild lässt sich nicht dekodieren.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="118"/>
        <source>There is not enough memory to read it.</source>
        <translation>Es ist nicht genug Speicher da, um sie zu lesen.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_import.cpp" line="33"/>
        <source>It cannot be read (is it there, and may Finbook read it?).</source>
        <translation>Sie lässt sich nicht lesen (gibt es sie, und darf Finbook sie lesen?).</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_import.cpp" line="45"/>
        <location filename="../model/src/picture/picture_import.cpp" line="49"/>
        <source>It is larger than %1 MB.</source>
        <translation>Sie ist größer als %1 MB.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="44"/>
        <source>The picture is empty.</source>
        <translation>Das Bild ist leer.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="49"/>
        <location filename="../model/src/picture/picture_object.cpp" line="275"/>
        <source>There is not enough memory for the picture.</source>
        <translation>Für das Bild ist nicht genug Speicher da.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="55"/>
        <source>The picture could not be encoded to be saved: %1</source>
        <translation>Das Bild ließ sich zum Speichern nicht kodieren: %1</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="71"/>
        <source>The picture&apos;s outline cannot be traced: %1</source>
        <translation>Der Umriss des Bildes lässt sich nicht nachzeichnen: %1</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="75"/>
        <source>The picture is fully transparent: nothing of it shows.</source>
        <translation>Das Bild ist ganz durchsichtig: Nichts davon ist zu sehen.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="87"/>
        <source>The picture&apos;s outline cannot be meshed: %1</source>
        <translation>Der Umriss des Bildes lässt sich nicht vernetzen: %1</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="288"/>
        <source>The object has no picture.</source>
        <translation>Das Objekt hat kein Bild.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="268"/>
        <source>The posed picture is too large to keep (at most %1 pixels wide and high).</source>
        <translation>Das posierte Bild ist zu groß, um es zu behalten (höchstens %1 Pixel breit und hoch).</translation>
    </message>
</context>
<context>
    <name>QCommandLineParser</name>
    <message>
        <location filename="../app/main.cpp" line="26"/>
        <source>Displays help on commandline options.</source>
        <translation>Zeigt Hilfe zu den Kommandozeilenoptionen an.</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="27"/>
        <source>Displays help including Qt specific options.</source>
        <translation>Zeigt Hilfe einschließlich Qt-spezifischer Optionen an.</translation>
    </message>
</context>
<context>
    <name>Reference</name>
    <message>
        <location filename="../model/src/reference/reference_commands.cpp" line="16"/>
        <source>Import Reference</source>
        <translation>Referenz importieren</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_commands.cpp" line="18"/>
        <source>Reference Opacity</source>
        <translation>Deckkraft der Referenz</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_commands.cpp" line="20"/>
        <source>Show or Hide Reference</source>
        <translation>Referenz ein- oder ausblenden</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_commands.cpp" line="22"/>
        <source>Lock or Unlock Reference</source>
        <translation>Referenz sperren oder entsperren</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/tool_reference.cpp" line="26"/>
        <location filename="../model/src/reference/reference_commands.cpp" line="24"/>
        <source>Move Reference</source>
        <translation>Referenz verschieben</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/tool_reference.cpp" line="22"/>
        <location filename="../model/src/reference/reference_commands.cpp" line="26"/>
        <source>Scale Reference</source>
        <translation>Referenz skalieren</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/tool_reference.cpp" line="24"/>
        <location filename="../model/src/reference/reference_commands.cpp" line="28"/>
        <source>Rotate Reference</source>
        <translation>Referenz drehen</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_commands.cpp" line="30"/>
        <source>Reference Frame Rate</source>
        <translation>Bildrate der Referenz</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_commands.cpp" line="91"/>
        <source>Remove Reference</source>
        <translation>Referenz entfernen</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_import.cpp" line="34"/>
        <source>“%1” cannot be used as a reference: %2</source>
        <translation>„%1“ kann nicht als Referenz verwendet werden: %2</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_import.cpp" line="44"/>
        <source>It cannot be read (is it there, and may Finbook read it?).</source>
        <translation>Sie lässt sich nicht lesen (gibt es sie, und darf Finbook sie lesen?).</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_import.cpp" line="67"/>
        <source>It is larger than %1 MB.</source>
        <translation>Sie ist größer als %1 MB.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_import.cpp" line="53"/>
        <source>It is empty.</source>
        <translation>Sie ist leer.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_media.cpp" line="111"/>
        <location filename="../model/src/reference/reference_media.cpp" line="135"/>
        <source>The file is empty.</source>
        <translation>Die Datei ist leer.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_media.cpp" line="69"/>
        <source>Its picture cannot be decoded.</source>
        <translation>Ihr Bild lässt sich nicht dekodieren.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="85"/>
        <source>Its SVG declares entities, which Finbook does not expand.</source>
        <translation>Ihr SVG deklariert Entitäten, die Finbook nicht auflöst.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="113"/>
        <location filename="../model/src/reference/reference_svg.cpp" line="215"/>
        <source>It is not a valid SVG picture.</source>
        <translation>Es ist kein gültiges SVG-Bild.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="152"/>
        <source>Its SVG uses an element inside itself (a loop of &lt;use&gt;).</source>
        <translation>Ihr SVG verwendet ein Element in sich selbst (eine Schleife von &lt;use&gt;).</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="210"/>
        <source>SVG pictures are drawn only where Finbook runs with its graphical application (their text needs its fonts).</source>
        <translation>SVG-Bilder werden nur gezeichnet, wo Finbook mit seiner grafischen Anwendung läuft (ihr Text braucht deren Schriften).</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="185"/>
        <source>The reference&apos;s SVG pictures took all the time Finbook spends drawing them.</source>
        <translation>Die SVG-Bilder der Referenz haben die ganze Zeit verbraucht, die Finbook für ihr Zeichnen aufwendet.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="193"/>
        <source>Its compressed SVG is damaged or larger than 16 MB.</source>
        <translation>Ihr komprimiertes SVG ist beschädigt oder größer als 16 MB.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="197"/>
        <source>Its SVG is larger than 16 MB.</source>
        <translation>Ihr SVG ist größer als 16 MB.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="204"/>
        <source>Its SVG paints more than 100,000 elements (counting what &lt;use&gt; repeats), more than Finbook draws for a reference.</source>
        <translation>Ihr SVG zeichnet mehr als 100.000 Elemente (mitgezählt, was &lt;use&gt; wiederholt), mehr als Finbook für eine Referenz zeichnet.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="221"/>
        <source>Its SVG has no size.</source>
        <translation>Ihr SVG hat keine Größe.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="228"/>
        <location filename="../model/src/reference/video_decoder.cpp" line="184"/>
        <location filename="../model/src/reference/video_decoder.cpp" line="189"/>
        <location filename="../model/src/reference/video_decoder.cpp" line="193"/>
        <location filename="../model/src/reference/video_decoder.cpp" line="221"/>
        <source>There is not enough memory to read it.</source>
        <translation>Zum Lesen reicht der Speicher nicht.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="257"/>
        <source>Its SVG takes too long to draw (more than %1 s), more than Finbook spends on a reference.</source>
        <translation>Ihr SVG braucht zu lange zum Zeichnen (mehr als %1 s), länger als Finbook für eine Referenz aufwendet.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/video_decoder.cpp" line="197"/>
        <location filename="../model/src/reference/video_decoder.cpp" line="201"/>
        <source>It is not a picture or a video Finbook can read, or it is damaged.</source>
        <translation>Es ist kein Bild oder Video, das Finbook lesen kann, oder es ist beschädigt.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/video_decoder.cpp" line="204"/>
        <source>It is damaged: its streams cannot be read.</source>
        <translation>Es ist beschädigt: seine Datenströme lassen sich nicht lesen.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/video_decoder.cpp" line="208"/>
        <source>It holds no picture Finbook can decode.</source>
        <translation>Es enthält kein Bild, das Finbook dekodieren kann.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/video_decoder.cpp" line="213"/>
        <source>Its pictures are empty or larger than 16384 pixels a side.</source>
        <translation>Seine Bilder sind leer oder größer als 16384 Pixel je Seite.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/video_decoder.cpp" line="231"/>
        <source>Its pictures cannot be decoded.</source>
        <translation>Seine Bilder lassen sich nicht dekodieren.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/video_decoder.cpp" line="238"/>
        <source>Its first picture cannot be decoded.</source>
        <translation>Sein erstes Bild lässt sich nicht dekodieren.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_sequence.cpp" line="75"/>
        <source>No picture was chosen.</source>
        <translation>Es wurde kein Bild gewählt.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_sequence.cpp" line="78"/>
        <source>A sequence of more than %1 pictures cannot be used as a reference.</source>
        <translation>Eine Folge von mehr als %1 Bildern kann nicht als Referenz dienen.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_sequence.cpp" line="87"/>
        <source>The pictures together are larger than %1 MB.</source>
        <translation>Die Bilder sind zusammen größer als %1 MB.</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/reference/reference_sequence.cpp" line="108"/>
        <source>%1 and %n more</source>
        <extracomment>%1 is the first file&apos;s name, %n how many pictures follow it</extracomment>
        <translation>
            <numerusform>%1 und %n weiteres</numerusform>
            <numerusform>%1 und %n weitere</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RigPrompt</name>
    <message>
        <location filename="../ui/src/rig/rig_prompt.cpp" line="20"/>
        <source>&quot;%1&quot; is posed. Removing its rig sends the drawing back to rest. (Apply Pose to Drawing first keeps the pose.)</source>
        <translation>„%1“ ist posiert. Wenn das Rig entfernt wird, kehrt die Zeichnung in die Ruhelage zurück. (Erst „Pose auf Zeichnung anwenden“ behält die Pose.)</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/rig_prompt.cpp" line="24"/>
        <source>Discard the Pose?</source>
        <translation>Pose verwerfen?</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/rig_prompt.cpp" line="22"/>
        <source>&quot;%1&quot; is posed. Replacing its rig sends the drawing back to rest. (Apply Pose to Drawing first keeps the pose.)</source>
        <translation>„%1“ ist posiert. Wenn sein Rig ersetzt wird, kehrt die Zeichnung in die Ruhelage zurück. (Mit „Pose auf Zeichnung anwenden“ bleibt die Pose vorher erhalten.)</translation>
    </message>
</context>
<context>
    <name>Sound</name>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="90"/>
        <source>The file is not a sound Finbook can read (WAV, FLAC, MP3, Ogg, Opus, AAC or M4A), or it is damaged.</source>
        <translation>Die Datei ist kein Ton, den Finbook lesen kann (WAV, FLAC, MP3, Ogg, Opus, AAC oder M4A), oder sie ist beschädigt.</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="211"/>
        <source>It holds more sound than a file of %1 KB can hold when it is real sound (more than %2 min; hostile or damaged files announce hours of sound in a few kilobytes). Convert it to WAV, FLAC or MP3 and import it again.</source>
        <translation>Sie enthält mehr Sound, als eine Datei von %1 KB mit echtem Sound enthalten kann (mehr als %2 min; bösartige oder beschädigte Dateien kündigen in wenigen Kilobyte Stunden an). Wandeln Sie sie in WAV, FLAC oder MP3 um und importieren Sie sie erneut.</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="240"/>
        <source>With the soundtrack&apos;s other clips it would make more than %1 min of sound, the most Finbook decodes from sound files of this size.</source>
        <translation>Zusammen mit den anderen Clips der Tonspur ergäbe das mehr als %1 min Sound, das Meiste, was Finbook aus Sounddateien dieser Größe dekodiert.</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="251"/>
        <source>The file is empty.</source>
        <translation>Die Datei ist leer.</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="253"/>
        <source>The file is incomplete: its sound data is cut off. Import the complete file.</source>
        <translation>Die Datei ist unvollständig: ihre Tondaten brechen ab. Importieren Sie die vollständige Datei.</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="261"/>
        <location filename="../model/src/sound/sound_decode.cpp" line="265"/>
        <location filename="../model/src/sound/sound_decode.cpp" line="269"/>
        <location filename="../model/src/sound/sound_decode.cpp" line="305"/>
        <source>There is not enough memory to read the sound.</source>
        <translation>Zum Lesen des Tons ist nicht genug Speicher vorhanden.</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="279"/>
        <source>The file holds no sound Finbook can play.</source>
        <translation>Die Datei enthält keinen Ton, den Finbook abspielen kann.</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="197"/>
        <source>Its sample rate, %1 Hz, is outside the %2 to %3 Hz Finbook plays (real recordings use 8,000 to 192,000).</source>
        <translation>Ihre Abtastrate von %1 Hz liegt außerhalb der %2 bis %3 Hz, die Finbook abspielt (echte Aufnahmen nutzen 8.000 bis 192.000).</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="294"/>
        <source>It has %1 channels; Finbook plays at most %2.</source>
        <translation>Sie hat %1 Kanäle; Finbook spielt höchstens %2.</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="353"/>
        <source>The sound is longer than %1 minutes, the longest Finbook plays.</source>
        <translation>Der Ton ist länger als %1 Minuten, die längste Dauer, die Finbook abspielt.</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="362"/>
        <source>The file holds no sound Finbook can play (no audio could be decoded from it).</source>
        <translation>Die Datei enthält keinen Ton, den Finbook abspielen kann (es ließ sich kein Ton daraus dekodieren).</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="369"/>
        <source>The file is incomplete: it announces %1 s of sound but holds only %2 s. Import the complete file.</source>
        <translation>Die Datei ist unvollständig: sie kündigt %1 s Ton an, enthält aber nur %2 s. Importieren Sie die vollständige Datei.</translation>
    </message>
</context>
<context>
    <name>StrokeEditing</name>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="124"/>
        <source>There is no frame to draw on. Insert a frame first.</source>
        <translation>Es gibt kein Einzelbild, auf dem gezeichnet werden kann. Fügen Sie zuerst ein Einzelbild ein.</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="127"/>
        <source>The object &quot;%1&quot; is locked. Unlock it in the Objects panel to draw on it.</source>
        <translation>Das Objekt „%1“ ist gesperrt. Entsperren Sie es im Bedienfeld Objekte, um darauf zu zeichnen.</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="130"/>
        <source>The object &quot;%1&quot; is hidden. Show it in the Objects panel to draw on it.</source>
        <translation>Das Objekt „%1“ ist ausgeblendet. Blenden Sie es im Bedienfeld Objekte ein, um darauf zu zeichnen.</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="152"/>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="191"/>
        <source>%1 (pose applied)</source>
        <translation>%1 (Pose angewendet)</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="288"/>
        <source>Delete Strokes</source>
        <translation>Striche löschen</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="288"/>
        <source>Delete Picture</source>
        <translation>Bild löschen</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="410"/>
        <source>Cut</source>
        <translation>Ausschneiden</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="486"/>
        <source>The clipboard holds strokes this version of Finbook cannot read.</source>
        <translation>Die Zwischenablage enthält Striche, die diese Finbook-Version nicht lesen kann.</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="496"/>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="497"/>
        <source>Paste</source>
        <translation>Einfügen</translation>
    </message>
</context>
<context>
    <name>Thumbnail</name>
    <message>
        <location filename="../app/thumbnail/first_frame.cpp" line="54"/>
        <source>it is not a regular file</source>
        <translation>es ist keine gewöhnliche Datei</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/first_frame.cpp" line="393"/>
        <source>Cannot make a thumbnail of &quot;%1&quot;: %2</source>
        <translation>Für „%1“ kann keine Vorschau erstellt werden: %2</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/first_frame.cpp" line="442"/>
        <source>a checksum does not match, so the file is damaged.</source>
        <translation>eine Prüfsumme stimmt nicht, die Datei ist also beschädigt.</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/first_frame.cpp" line="444"/>
        <source>it holds data that this version of Finbook does not know.</source>
        <translation>sie enthält Daten, die diese Version von Finbook nicht kennt.</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/first_frame.cpp" line="447"/>
        <source>the file is damaged or incomplete.</source>
        <translation>die Datei ist beschädigt oder unvollständig.</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/thumbnail_command.cpp" line="138"/>
        <source>Usage: finbook thumbnail FILE OUT.png SIZE</source>
        <translation>Aufruf: finbook thumbnail DATEI AUSGABE.png GRÖSSE</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/thumbnail_command.cpp" line="144"/>
        <source>The thumbnail size &quot;%1&quot; is not a whole number from 1 to %2.</source>
        <translation>Die Vorschaugröße „%1“ ist keine ganze Zahl von 1 bis %2.</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/thumbnail_command.cpp" line="153"/>
        <source>Cannot make a thumbnail of &quot;%1&quot;: it has no frame.</source>
        <translation>Für „%1“ kann keine Vorschau erstellt werden: sie hat kein Bild.</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/thumbnail_command.cpp" line="163"/>
        <source>Cannot make a thumbnail of &quot;%1&quot;: there is not enough memory.</source>
        <translation>Für „%1“ kann keine Vorschau erstellt werden: nicht genug Arbeitsspeicher.</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/thumbnail_command.cpp" line="169"/>
        <source>Cannot write the thumbnail &quot;%1&quot;: %2.</source>
        <translation>Die Vorschau „%1“ kann nicht geschrieben werden: %2.</translation>
    </message>
</context>
<context>
    <name>finbook::model::FrameListModel</name>
    <message numerus="yes">
        <location filename="../model/src/frame_list_model.cpp" line="151"/>
        <source>Frame %1, held for %n frame(s)</source>
        <translation>
            <numerusform>Einzelbild %1, %n Einzelbild lang gehalten</numerusform>
            <numerusform>Einzelbild %1, %n Einzelbilder lang gehalten</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/frame_list_model.cpp" line="152"/>
        <source>Frame %1</source>
        <translation>Einzelbild %1</translation>
    </message>
</context>
<context>
    <name>finbook::model::lipsync</name>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="31"/>
        <source>The file holds no mouth shapes.</source>
        <translation>Die Datei enthält keine Mundformen.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="44"/>
        <source>The file is larger than %1 MiB, too large for lip sync timings.</source>
        <translation>Die Datei ist größer als %1 MiB, zu groß für Lippensynchron-Zeiten.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="55"/>
        <source>The file is empty.</source>
        <translation>Die Datei ist leer.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="149"/>
        <source>Line %1: &quot;%2&quot; is not a time from 0 to %3 seconds.</source>
        <translation>Zeile %1: „%2“ ist keine Zeit von 0 bis %3 Sekunden.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="158"/>
        <source>Line %1: the time goes backwards.</source>
        <translation>Zeile %1: die Zeit läuft rückwärts.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="165"/>
        <source>Line %1: the mouth cue ends before it starts.</source>
        <translation>Zeile %1: die Mundform endet, bevor sie beginnt.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="172"/>
        <source>The file holds more than %1 mouth cues.</source>
        <translation>Die Datei enthält mehr als %1 Mundformen.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="179"/>
        <source>Line %1: &quot;%2&quot; is not a mouth shape.</source>
        <translation>Zeile %1: „%2“ ist keine Mundform.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="213"/>
        <source>The frame rate %1 is not a number above 0 and up to %2.</source>
        <translation>Die Bildrate %1 ist keine Zahl über 0 und bis %2.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="221"/>
        <source>The file ends too early, after line %1.</source>
        <translation>Die Datei endet zu früh, nach Zeile %1.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="228"/>
        <source>Line %1: &quot;%2&quot; is not a whole number from %3 to %4.</source>
        <translation>Zeile %1: „%2“ ist keine ganze Zahl von %3 bis %4.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="256"/>
        <source>The Papagayo file holds no phonemes.</source>
        <translation>Die Papagayo-Datei enthält keine Phoneme.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="299"/>
        <source>Line 1: a Papagayo file starts with &quot;lipsync version 1&quot;.</source>
        <translation>Zeile 1: Eine Papagayo-Datei beginnt mit „lipsync version 1“.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="309"/>
        <source>Line %1: the frame rate &quot;%2&quot; is not a number above 0 and up to %3.</source>
        <translation>Zeile %1: die Bildrate „%2“ ist keine Zahl über 0 und bis %3.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="354"/>
        <source>Line %1 is not a word (&quot;text, start frame, end frame, phoneme count&quot;).</source>
        <translation>Zeile %1 ist kein Wort („Text, Anfangsbild, Endbild, Anzahl Phoneme“).</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="380"/>
        <source>Line %1 is not a phoneme (&quot;frame name&quot;).</source>
        <translation>Zeile %1 ist kein Phonem („Bild Name“).</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="388"/>
        <source>Line %1: the phoneme at frame %2 comes after its word&apos;s end, frame %3.</source>
        <translation>Zeile %1: das Phonem in Bild %2 kommt nach dem Ende seines Worts, Bild %3.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="438"/>
        <source>The XML is damaged at line %1: %2.</source>
        <translation>Das XML ist in Zeile %1 beschädigt: %2.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="478"/>
        <source>Mouth cue %1: its &quot;%2&quot; is not a time from 0 to %3 seconds.</source>
        <translation>Mundform %1: ihr „%2“ ist keine Zeit von 0 bis %3 Sekunden.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="501"/>
        <source>Mouth cue %1 ends before it starts.</source>
        <translation>Mundform %1 endet, bevor sie beginnt.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="508"/>
        <source>Mouth cue %1: its &quot;value&quot; &quot;%2&quot; is not a mouth shape.</source>
        <translation>Mundform %1: ihr „value“ „%2“ ist keine Mundform.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="514"/>
        <source>Mouth cue %1: the time goes backwards.</source>
        <translation>Mundform %1: die Zeit läuft rückwärts.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="537"/>
        <source>The JSON is damaged at character %1: %2.</source>
        <translation>Das JSON ist bei Zeichen %1 beschädigt: %2.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="543"/>
        <source>The JSON has no &quot;mouthCues&quot; list: it is not a Rhubarb Lip Sync result.</source>
        <translation>Das JSON hat keine Liste „mouthCues“: Es ist kein Ergebnis von Rhubarb Lip Sync.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="566"/>
        <source>Line %1: the XML&apos;s root is &lt;%2&gt;, not &lt;rhubarbResult&gt;: it is not a Rhubarb Lip Sync result.</source>
        <translation>Zeile %1: die Wurzel des XML ist &lt;%2&gt;, nicht &lt;rhubarbResult&gt;: Es ist kein Ergebnis von Rhubarb Lip Sync.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="601"/>
        <source>Line %1 is not &quot;seconds, tab, shape letter&quot;.</source>
        <translation>Zeile %1 ist nicht „Sekunden, Tabulator, Formbuchstabe“.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="629"/>
        <source>Line %1: Moho switch data starts with &quot;MohoSwitch1&quot;.</source>
        <translation>Zeile %1: Moho-Switch-Daten beginnen mit „MohoSwitch1“.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="644"/>
        <source>Line %1 is not &quot;frame shape&quot;.</source>
        <translation>Zeile %1 ist nicht „Bild Form“.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="649"/>
        <source>Line %1: &quot;%2&quot; is not a frame number from 1 to %3.</source>
        <translation>Zeile %1: „%2“ ist keine Bildnummer von 1 bis %3.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="671"/>
        <source>Line %1: the letter &quot;%2&quot; is among Preston Blair&apos;s names; a file uses one naming or the other.</source>
        <translation>Zeile %1: der Buchstabe „%2“ steht unter Preston Blairs Namen; eine Datei benutzt die eine Benennung oder die andere.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="724"/>
        <source>&quot;%1&quot; could not be opened: %2.</source>
        <translation>„%1“ konnte nicht geöffnet werden: %2.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="746"/>
        <source>&quot;%1&quot; is not lip sync timings that Finbook reads: Papagayo (.pgo), Moho switch data (.dat) or Rhubarb Lip Sync (.tsv, .json, .xml).</source>
        <translation>„%1“ sind keine Lippensynchron-Zeiten, die Finbook liest: Papagayo (.pgo), Moho-Switch-Daten (.dat) oder Rhubarb Lip Sync (.tsv, .json, .xml).</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="756"/>
        <source>Lip sync timings</source>
        <translation>Lippensynchron-Zeiten</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="137"/>
        <source>The sound&apos;s sample rate (%1 Hz) is not one speech can be recognised at.</source>
        <translation>Die Abtastrate des Tons (%1 Hz) erlaubt keine Spracherkennung.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="142"/>
        <source>The sound is too short to hold speech (less than a tenth of a second).</source>
        <translation>Der Ton ist zu kurz für Sprache (weniger als eine Zehntelsekunde).</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="146"/>
        <source>The sound is damaged: some of its samples are not numbers.</source>
        <translation>Der Ton ist beschädigt: Einige seiner Abtastwerte sind keine Zahlen.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="151"/>
        <source>The sound is silent: there is no speech to recognise. Check that the clip is the one with the dialogue and that it is not muted.</source>
        <translation>Der Ton ist stumm: Es gibt keine Sprache zu erkennen. Prüfen Sie, ob der Clip der mit dem Dialog ist und nicht stummgeschaltet ist.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="173"/>
        <source>The speech models are not installed (looked in %1; on Debian and Ubuntu install the package pocketsphinx-en-us). Mouth shapes follow the loudness only.</source>
        <translation>Die Sprachmodelle sind nicht installiert (gesucht in %1; unter Debian und Ubuntu das Paket pocketsphinx-en-us installieren). Die Mundformen folgen nur der Lautstärke.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="520"/>
        <source>The dialogue could not be prepared for recognition: %1</source>
        <translation>Der Dialog konnte nicht für die Erkennung vorbereitet werden: %1</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="529"/>
        <source>The speech models are damaged: %1</source>
        <translation>Die Sprachmodelle sind beschädigt: %1</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="593"/>
        <source>Speech recognition failed: %1</source>
        <translation>Die Spracherkennung ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="602"/>
        <source>Lip sync was canceled.</source>
        <translation>Die Lippensynchronisation wurde abgebrochen.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="854"/>
        <source>The speech models could not be loaded (%1). Mouth shapes follow the loudness only.</source>
        <translation>Die Sprachmodelle konnten nicht geladen werden (%1). Die Mundformen folgen nur der Lautstärke.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="866"/>
        <source>The dialogue does not match the sound: the mouth follows the phones heard, without the dialogue.</source>
        <translation>Der Dialog passt nicht zum Ton: Der Mund folgt den gehörten Lauten, ohne den Dialog.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::BetweenFitView</name>
    <message>
        <location filename="../ui/src/inbetween/between_fit_view.cpp" line="38"/>
        <source>Drag from a line of the first drawing to where it belongs on the second to pin it there; drag a pin to move it, right-click it to take it away.</source>
        <translation>Ziehen Sie von einer Linie der ersten Zeichnung dorthin, wo sie auf der zweiten hingehört, um sie dort festzupinnen; ziehen Sie einen Pin, um ihn zu verschieben, Rechtsklick entfernt ihn.</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/between_fit_view.cpp" line="137"/>
        <source>No drawing to fit</source>
        <translation>Keine Zeichnung anzupassen</translation>
    </message>
</context>
<context>
    <name>finbook::ui::BezierEditorDialog</name>
    <message>
        <location filename="../ui/src/camera/bezier_editor.cpp" line="117"/>
        <source>Camera Easing Curve</source>
        <translation>Easing-Kurve der Kamera</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/bezier_editor.cpp" line="124"/>
        <source>Ease</source>
        <translation>Weich</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/bezier_editor.cpp" line="125"/>
        <source>Ease In</source>
        <translation>Langsam beginnen</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/bezier_editor.cpp" line="126"/>
        <source>Ease Out</source>
        <translation>Langsam enden</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/bezier_editor.cpp" line="127"/>
        <source>Ease In and Out</source>
        <translation>Langsam beginnen und enden</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/bezier_editor.cpp" line="128"/>
        <source>Overshoot</source>
        <translation>Überschwingen</translation>
    </message>
</context>
<context>
    <name>finbook::ui::BoneTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/skeleton/tool_bone.h" line="40"/>
        <source>Bone</source>
        <translation>Knochen</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/skeleton/tool_bone.h" line="43"/>
        <source>build a skeleton and pose the drawing by its bones</source>
        <translation>ein Skelett bauen und die Zeichnung an seinen Knochen posieren</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="55"/>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="168"/>
        <source>Build Skeleton</source>
        <translation>Skelett erstellen</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="56"/>
        <source>The object is posed with another deformer. Building a skeleton discards that pose. Build it anyway?</source>
        <translation>Das Objekt ist mit einem anderen Verformer posiert. Beim Erstellen eines Skeletts wird diese Pose verworfen. Trotzdem erstellen?</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="186"/>
        <source>Joined to %1. Shift-drag its root to join it elsewhere; right-click it to detach it.</source>
        <translation>Mit %1 verbunden. Ziehen Sie die Wurzel mit Umschalt an eine andere Stelle, um es dort zu verbinden; Rechtsklick darauf löst es.</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="261"/>
        <source>Click on a visible, unlocked drawing to give it a skeleton.</source>
        <translation>Klicken Sie auf eine sichtbare, nicht gesperrte Zeichnung, um ihr ein Skelett zu geben.</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="268"/>
        <source>Drag a joint to move it, click a bone to insert a joint; right-click a joint to delete it.</source>
        <translation>Ziehen Sie ein Gelenk, um es zu verschieben, klicken Sie auf einen Knochen, um ein Gelenk einzufügen; Rechtsklick auf ein Gelenk löscht es.</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="271"/>
        <source>Drag a bone to turn it, a joint to pull it, the root to move the object; press L over a joint to lock it; Shift-drag the root onto another part to join them.</source>
        <translation>Ziehen Sie einen Knochen, um ihn zu drehen, ein Gelenk, um es zu ziehen, die Wurzel, um das Objekt zu verschieben; L über einem Gelenk sperrt es; die Wurzel mit Umschalt auf ein anderes Teil ziehen verbindet beide.</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="366"/>
        <source>Drop the root on a bone of another part to join them.</source>
        <translation>Legen Sie die Wurzel auf einem Knochen eines anderen Teils ab, um beide zu verbinden.</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="374"/>
        <source>%1 hangs from this part already, so it cannot hang from it in turn.</source>
        <translation>%1 hängt bereits an diesem Teil und kann daher nicht umgekehrt daran hängen.</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="115"/>
        <source>Edit Joints: drag a joint to move it, click a bone to insert a joint.</source>
        <translation>Gelenke bearbeiten: Ziehen Sie ein Gelenk, um es zu verschieben, klicken Sie auf einen Knochen, um ein Gelenk einzufügen.</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="130"/>
        <source>Reset the pose or apply it to the drawing before editing joints.</source>
        <translation>Setzen Sie die Pose zurück oder wenden Sie sie auf die Zeichnung an, bevor Sie Gelenke bearbeiten.</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="192"/>
        <source>Unlock Joint</source>
        <translation>Gelenk entsperren</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="192"/>
        <source>Lock Joint</source>
        <translation>Gelenk sperren</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="197"/>
        <source>Reset Bone Pose</source>
        <translation>Knochenpose zurücksetzen</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="200"/>
        <source>Edit Joints</source>
        <translation>Gelenke bearbeiten</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="205"/>
        <source>Insert Joint Here</source>
        <translation>Gelenk hier einfügen</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="207"/>
        <source>Delete Joint</source>
        <translation>Gelenk löschen</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="211"/>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="263"/>
        <source>Make Root Joint</source>
        <translation>Zum Wurzelgelenk machen</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="220"/>
        <source>Detach from %1</source>
        <translation>Von %1 lösen</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="223"/>
        <source>Make Character Root</source>
        <translation>Zur Wurzel der Figur machen</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="224"/>
        <source>Join Overlapping Parts</source>
        <translation>Überlappende Teile verbinden</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="275"/>
        <source>No part overlaps another part&apos;s skeleton.</source>
        <translation>Kein Teil überlappt das Skelett eines anderen Teils.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="279"/>
        <source>Joined %n part(s).</source>
        <translation>
            <numerusform>%n Teil verbunden.</numerusform>
            <numerusform>%n Teile verbunden.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::ui::BrushToolBar</name>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="16"/>
        <source>Brush</source>
        <translation>Pinsel</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="23"/>
        <source>Pressure</source>
        <translation>Druck</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="37"/>
        <source>Width:</source>
        <translation>Breite:</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="42"/>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="44"/>
        <source>Smoothing:</source>
        <translation>Glättung:</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="47"/>
        <source>How much a stroke is smoothed when the pen lifts</source>
        <translation>Wie stark ein Strich beim Absetzen des Stifts geglättet wird</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="49"/>
        <source>Stabiliser:</source>
        <translation>Stabilisator:</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="52"/>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="53"/>
        <source>Steadies the line while you draw: the ink follows the pen on a string this long (4 screen pixels a step), so a shaky hand draws a smooth line. Off: the ink is under the pen.</source>
        <translation>Beruhigt die Linie beim Zeichnen: Die Tinte folgt dem Stift an einer Schnur dieser Länge (4 Bildschirmpixel je Stufe), sodass eine zittrige Hand eine glatte Linie zeichnet. Aus: Die Tinte liegt unter dem Stift.</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="58"/>
        <source>A tablet&apos;s pressure sets the line&apos;s width; off, every line has the full width</source>
        <translation>Der Druck des Grafiktabletts bestimmt die Linienbreite; aus, hat jede Linie die volle Breite</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="116"/>
        <source>Pen colour %1</source>
        <translation>Stiftfarbe %1</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="117"/>
        <source>Pen colour %1 (%2)</source>
        <translation>Stiftfarbe %1 (%2)</translation>
    </message>
</context>
<context>
    <name>finbook::ui::CageActions</name>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="33"/>
        <source>&amp;Fit Cage</source>
        <translation>Käfig an&amp;passen</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="35"/>
        <source>Put a coarse cage around the current object in one step</source>
        <translation>Einen groben Käfig in einem Schritt um das aktuelle Objekt legen</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="36"/>
        <source>Shift+C</source>
        <translation>Shift+C</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="37"/>
        <source>Edit Cage &amp;Shape</source>
        <translation>Käfig&amp;form bearbeiten</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="41"/>
        <source>Change the cage itself (move, add or delete corners) instead of posing with it</source>
        <translation>Den Käfig selbst ändern (Ecken verschieben, hinzufügen oder löschen), statt damit zu posieren</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="67"/>
        <source>Corners </source>
        <translation>Ecken </translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="68"/>
        <source>About how many corners Fit Cage gives the cage</source>
        <translation>Ungefähr wie viele Ecken „Käfig anpassen“ dem Käfig gibt</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="82"/>
        <source>Choose an unlocked object with strokes to fit a cage to.</source>
        <translation>Wählen Sie ein nicht gesperrtes Objekt mit Strichen, um einen Käfig daran anzupassen.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::CageTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/cage/tool_cage.h" line="23"/>
        <source>Cage</source>
        <translation>Käfig</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/cage/tool_cage.h" line="26"/>
        <source>draw a cage around the drawing, then drag its corners to bend it</source>
        <translation>einen Käfig um die Zeichnung ziehen und sie an seinen Ecken biegen</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/tool_cage.cpp" line="132"/>
        <source>Choose an object first: the cage goes around it.</source>
        <translation>Wählen Sie zuerst ein Objekt: Der Käfig wird darum gelegt.</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/tool_cage.cpp" line="258"/>
        <source>A cage needs at least three corners.</source>
        <translation>Ein Käfig braucht mindestens drei Ecken.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::CameraTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/camera/tool_camera.h" line="30"/>
        <source>Camera</source>
        <translation>Kamera</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/camera/tool_camera.h" line="33"/>
        <source>frame the shot: move, zoom and turn the camera</source>
        <translation>die Einstellung wählen: die Kamera bewegen, zoomen und drehen</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="189"/>
        <source>Easing to the Next Key</source>
        <translation>Übergang zum nächsten Schlüsselbild</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="193"/>
        <source>Linear</source>
        <translation>Linear</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="194"/>
        <source>Ease In</source>
        <translation>Langsam beginnen</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="195"/>
        <source>Ease Out</source>
        <translation>Langsam enden</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="196"/>
        <source>Ease In and Out</source>
        <translation>Langsam beginnen und enden</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="197"/>
        <source>Hold, Then Cut</source>
        <translation>Halten, dann schneiden</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="208"/>
        <source>Bézier Curve...</source>
        <translation>Bézierkurve...</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="214"/>
        <source>Delete Camera Key</source>
        <translation>Kamera-Schlüsselbild löschen</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="217"/>
        <source>Reset Camera</source>
        <translation>Kamera zurücksetzen</translation>
    </message>
</context>
<context>
    <name>finbook::ui::CanvasWidget</name>
    <message>
        <location filename="../ui/src/canvas/canvas_widget.cpp" line="311"/>
        <source>The layer &quot;%1&quot; is locked: unlock it (Layer &gt; Lock Layer, or its padlock in the timeline) to draw on it.</source>
        <translation>Die Ebene „%1“ ist gesperrt: Entsperren Sie sie (Ebene &gt; Ebene sperren oder ihr Schloss in der Zeitleiste), um darauf zu zeichnen.</translation>
    </message>
    <message>
        <location filename="../ui/src/canvas/canvas_widget.cpp" line="314"/>
        <source>The layer &quot;%1&quot; is hidden: show it (Layer &gt; Show Layer, or its eye in the timeline) to draw on it.</source>
        <translation>Die Ebene „%1“ ist ausgeblendet: Blenden Sie sie ein (Ebene &gt; Ebene anzeigen oder ihr Auge in der Zeitleiste), um darauf zu zeichnen.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ColorButton</name>
    <message>
        <location filename="../ui/src/widgets/color_button.cpp" line="13"/>
        <source>Choose a colour</source>
        <translation>Eine Farbe wählen</translation>
    </message>
    <message>
        <location filename="../ui/src/widgets/color_button.cpp" line="31"/>
        <source>Choose Colour</source>
        <translation>Farbe wählen</translation>
    </message>
</context>
<context>
    <name>finbook::ui::DeformActions</name>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="26"/>
        <source>&amp;Reset Pose</source>
        <translation>Pose &amp;zurücksetzen</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="30"/>
        <source>&amp;Apply Pose to Drawing</source>
        <translation>Pose auf Zeichnung &amp;anwenden</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="29"/>
        <source>Move the current object&apos;s pins, cage corners or bones back to their rest positions</source>
        <translation>Die Pins, Käfigecken oder Knochen des aktuellen Objekts in ihre Ruhepositionen zurücksetzen</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="32"/>
        <source>Make the posed drawing the object&apos;s new strokes; the pins, cage or skeleton stay where they are</source>
        <translation>Die posierte Zeichnung zu den neuen Strichen des Objekts machen; die Pins, der Käfig oder das Skelett bleiben, wo sie sind</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="34"/>
        <source>Remo&amp;ve Rig</source>
        <translation>Rig &amp;entfernen</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="37"/>
        <source>Take the pins, the cage or the skeleton off the current object</source>
        <translation>Die Pins, den Käfig oder das Skelett vom aktuellen Objekt entfernen</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="57"/>
        <source>The posed picture is now the object&apos;s picture: resampled once, it is a little softer. Undo brings back the original.</source>
        <translation>Das gestellte Bild ist jetzt das Bild des Objekts: einmal neu abgetastet, ist es etwas weicher. Rückgängig bringt das Original zurück.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/rig/deform_actions.cpp" line="74"/>
        <source>The pins fold the drawing: %n triangle(s) of its mesh turned over where the pins leave no room (View → Show Mesh shows them red)</source>
        <translation>
            <numerusform>Die Pins falten die Zeichnung: %n Dreieck ihres Netzes ist umgeklappt, wo die Pins keinen Platz lassen (Ansicht → Netz anzeigen zeigt es rot)</numerusform>
            <numerusform>Die Pins falten die Zeichnung: %n Dreiecke ihres Netzes sind umgeklappt, wo die Pins keinen Platz lassen (Ansicht → Netz anzeigen zeigt sie rot)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="79"/>
        <source>Preparing the deformation…</source>
        <translation>Verformung wird vorbereitet…</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="89"/>
        <source>R&amp;igidity</source>
        <translation>&amp;Steifigkeit</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="103"/>
        <source>Converged (Most Rigid)</source>
        <translation>Konvergiert (am starrsten)</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="104"/>
        <source>As in the Paper (Two Steps)</source>
        <translation>Wie in der Veröffentlichung (zwei Schritte)</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="105"/>
        <source>Stiffer (+1 Pass)</source>
        <translation>Steifer (+1 Durchgang)</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="106"/>
        <source>Stiffest (+3 Passes)</source>
        <translation>Am steifsten (+3 Durchgänge)</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="139"/>
        <source>Mesh density </source>
        <translation>Netzdichte </translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="140"/>
        <source>How fine the current object&apos;s deformation mesh is (1 = default)</source>
        <translation>Wie fein das Verformungsnetz des aktuellen Objekts ist (1 = Standard)</translation>
    </message>
</context>
<context>
    <name>finbook::ui::DocumentSettingsDialog</name>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="26"/>
        <source>Start again after the last frame</source>
        <translation>Nach dem letzten Einzelbild wieder von vorn beginnen</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="30"/>
        <source>Document Settings</source>
        <translation>Dokumenteinstellungen</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="32"/>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="35"/>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="40"/>
        <source>Last</source>
        <translation>Letztes</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="50"/>
        <source>to</source>
        <translation>bis</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="54"/>
        <source>&amp;Frame rate:</source>
        <translation>&amp;Bildrate:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="55"/>
        <source>Canvas size:</source>
        <translation>Leinwandgröße:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="56"/>
        <source>&amp;Background:</source>
        <translation>&amp;Hintergrund:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="57"/>
        <source>Loop:</source>
        <translation>Endlosschleife:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="58"/>
        <source>Play frames:</source>
        <translation>Einzelbilder abspielen:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="125"/>
        <source>Background Colour</source>
        <translation>Hintergrundfarbe</translation>
    </message>
</context>
<context>
    <name>finbook::ui::EraserTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_eraser.h" line="29"/>
        <source>Eraser</source>
        <translation>Radierer</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_eraser.h" line="30"/>
        <source>rub out parts of lines, or whole strokes</source>
        <translation>Teile von Linien oder ganze Striche wegradieren</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_eraser.cpp" line="160"/>
        <source>Erase</source>
        <translation>Radieren</translation>
    </message>
</context>
<context>
    <name>finbook::ui::EraserToolBar</name>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="11"/>
        <source>Eraser</source>
        <translation>Radierer</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="13"/>
        <source>Cut Lines</source>
        <translation>Linien schneiden</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="14"/>
        <source>Whole Strokes</source>
        <translation>Ganze Striche</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="25"/>
        <source>Erase the part of a line under the eraser (the rest is split into pieces)</source>
        <translation>Radiert den Teil einer Linie unter dem Radierer (der Rest wird in Stücke geteilt)</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="28"/>
        <source>Erase every stroke the eraser touches (or hold Shift when you start rubbing)</source>
        <translation>Radiert jeden Strich, den der Radierer berührt (oder Umschalt beim Beginn gedrückt halten)</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="31"/>
        <source>Size:</source>
        <translation>Größe:</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="35"/>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="36"/>
        <source>The eraser&apos;s diameter on the canvas</source>
        <translation>Der Durchmesser des Radierers auf der Zeichenfläche</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ExportDialog</name>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="59"/>
        <location filename="../ui/src/export/export_dialog.cpp" line="340"/>
        <source>Export Animation</source>
        <translation>Animation exportieren</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="67"/>
        <location filename="../ui/src/export/export_dialog.cpp" line="328"/>
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="79"/>
        <source>Animated GIF</source>
        <translation>Animiertes GIF</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="80"/>
        <source>MP4 video (H.264)</source>
        <translation>MP4-Video (H.264)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="81"/>
        <source>WebM video (VP9)</source>
        <translation>WebM-Video (VP9)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="82"/>
        <source>Animated PNG (APNG)</source>
        <translation>Animiertes PNG (APNG)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="83"/>
        <source>HTML flipbook (one file)</source>
        <translation>HTML-Daumenkino (eine Datei)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="84"/>
        <source>Lottie animation (JSON), for web pages and apps</source>
        <translation>Lottie-Animation (JSON), für Webseiten und Apps</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="85"/>
        <source>dotLottie animation (compressed Lottie)</source>
        <translation>dotLottie-Animation (komprimiertes Lottie)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="86"/>
        <source>PNG images (a folder)</source>
        <translation>PNG-Bilder (ein Ordner)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="87"/>
        <source>SVG vector images (a folder)</source>
        <translation>SVG-Vektorbilder (ein Ordner)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="88"/>
        <source>3D model (OBJ), the current frame</source>
        <translation>3D-Modell (OBJ), das aktuelle Einzelbild</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="89"/>
        <source>3D model (glTF binary), the current frame</source>
        <translation>Finbook, ein Daumenkino-Animationseditor.

  finbook [FILE]               FILE im Editor öffnen
  finbook info FILE            eine JSON-Zusammenfassung von FILE ausgeben
  finbook export FILE OUTDIR   jedes Einzelbild nach OUTDIR/frame_0001.png ... rendern
  finbook export FILE OUT      nach OUT.gif, .mp4, .webm, .apng oder .html exportieren
  finbook export FILE OUT.obj --frame N   Einzelbild N als 3D-Modell (OUT.obj, OUT.mtl)
  finbook export FILE OUT.glb --frame N   Einzelbild N als 3D-Modell (glTF binär)
  finbook export FILE... --format F --out-dir DIR   mehrere Dateien exportieren
  finbook thumbnail FILE OUT.png SIZE   das erste Einzelbild als PNG von höchstens SIZE px schreiben</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="93"/>
        <source>&amp;Browse...</source>
        <translation>&amp;Durchsuchen...</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="95"/>
        <source>Play range</source>
        <translation>Wiedergabebereich</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="96"/>
        <source>All frames</source>
        <translation>Alle Einzelbilder</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="97"/>
        <source>Frames</source>
        <translation>Einzelbilder</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="112"/>
        <source>Document background</source>
        <translation>Dokumenthintergrund</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="113"/>
        <source>Transparent</source>
        <translation>Transparent</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="114"/>
        <source>Colour</source>
        <translation>Farbe</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="118"/>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="119"/>
        <source>Start again after the last frame</source>
        <translation>Nach dem letzten Einzelbild wieder von vorn beginnen</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="120"/>
        <source>One file per drawing, with an exposure sheet</source>
        <translation>Eine Datei pro Zeichnung, mit Timing-Sheet</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="121"/>
        <source>Include refere&amp;nce</source>
        <translation>Refere&amp;nz einschließen</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="123"/>
        <source>Paint the reference picture or video under the drawing (not in SVG or 3D)</source>
        <translation>Das Referenzbild oder -video unter die Zeichnung malen (nicht bei SVG oder 3D)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="143"/>
        <source>to</source>
        <translation>bis</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="158"/>
        <source>&amp;Format:</source>
        <translation>&amp;Format:</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="159"/>
        <source>&amp;Save to:</source>
        <translation>&amp;Speichern in:</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="160"/>
        <source>F&amp;rames:</source>
        <translation>Einzel&amp;bilder:</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="161"/>
        <source>Sc&amp;ale:</source>
        <translation>S&amp;kalierung:</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="162"/>
        <source>&amp;Background:</source>
        <translation>&amp;Hintergrund:</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="163"/>
        <source>Frame ra&amp;te:</source>
        <translation>Bild&amp;rate:</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="164"/>
        <source>Loop:</source>
        <translation>Endlosschleife:</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="169"/>
        <source>&amp;Export</source>
        <translation>&amp;Exportieren</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="170"/>
        <source>Cancel Export</source>
        <translation>Export abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="271"/>
        <source>%1 x %2 pixels</source>
        <translation>%1 × %2 Pixel</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="274"/>
        <source>A 3D model holds the current frame (%1) only: its objects inflated, in their fill colours, with a .mtl file beside it. The frames, scale, background and frame rate do not apply.</source>
        <translation>Ein 3D-Modell enthält nur das aktuelle Einzelbild (%1): seine Objekte aufgeblasen, in ihren Füllfarben, mit einer .mtl-Datei daneben. Bilder, Skalierung, Hintergrund und Bildrate gelten hier nicht.</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="279"/>
        <source>A 3D model holds the current frame (%1) only: its objects inflated, in their fill colours, all in one file. The frames, scale, background and frame rate do not apply.</source>
        <translation>Ein 3D-Modell enthält nur das aktuelle Einzelbild (%1): seine Objekte aufgeblasen, in ihren Füllfarben, alles in einer Datei. Bilder, Skalierung, Hintergrund und Bildrate gelten hier nicht.</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="284"/>
        <source>This format needs the ffmpeg program, which was not found; install it (on Debian: apt install ffmpeg) first.</source>
        <translation>Dieses Format benötigt das Programm ffmpeg, das nicht gefunden wurde; installieren Sie es zuerst (unter Debian: apt install ffmpeg).</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="289"/>
        <source>The video carries the soundtrack, trimmed to the frames exported.</source>
        <translation>Das Video enthält die Tonspur, zugeschnitten auf die exportierten Bilder.</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="291"/>
        <source>The page carries the soundtrack; it plays with the frames once the viewer presses Play.</source>
        <translation>Die Seite enthält die Tonspur; sie läuft mit den Bildern, sobald der Betrachter auf Abspielen klickt.</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="293"/>
        <source>This format has no sound: the soundtrack is left out (MP4, WebM and HTML carry it).</source>
        <translation>Dieses Format hat keinen Ton: die Tonspur wird weggelassen (MP4, WebM und HTML enthalten sie).</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="337"/>
        <source>Export to Folder</source>
        <translation>In Ordner exportieren</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="341"/>
        <source>%1 files (*.%2)</source>
        <translation>%1-Dateien (*.%2)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="30"/>
        <source>Choose where to export the animation to.</source>
        <translation>Wählen Sie, wohin die Animation exportiert werden soll.</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="56"/>
        <source>Exporting...</source>
        <translation>Wird exportiert...</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="68"/>
        <source>Cancelling...</source>
        <translation>Wird abgebrochen...</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/export/export_dialog_run.cpp" line="86"/>
        <source>Exported %n file(s) to %1</source>
        <translation>
            <numerusform>%n Datei nach %1 exportiert</numerusform>
            <numerusform>%n Dateien nach %1 exportiert</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="99"/>
        <source>Export cancelled; nothing was written.</source>
        <translation>Export abgebrochen; es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="124"/>
        <source>&quot;%1&quot; already exists. Replace it?</source>
        <translation>„%1“ ist bereits vorhanden. Ersetzen?</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/export/export_dialog_run.cpp" line="125"/>
        <source>%n file(s) at the target already exist, such as &quot;%1&quot;. Replace them?</source>
        <translation>
            <numerusform>%n Datei am Ziel ist bereits vorhanden: „%1“. Ersetzen?</numerusform>
            <numerusform>%n Dateien am Ziel sind bereits vorhanden, etwa „%1“. Ersetzen?</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="128"/>
        <source>Replace Files?</source>
        <translation>Dateien ersetzen?</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="135"/>
        <source>Export Anyway?</source>
        <translation>Trotzdem exportieren?</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="137"/>
        <source>It may take a long time and a lot of disk space. Export anyway?</source>
        <translation>Das kann lange dauern und viel Speicherplatz belegen. Trotzdem exportieren?</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="145"/>
        <source>Cannot Export</source>
        <translation>Export nicht möglich</translation>
    </message>
</context>
<context>
    <name>finbook::ui::EyedropperTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_eyedropper.h" line="29"/>
        <source>Eyedropper</source>
        <translation>Pipette</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_eyedropper.h" line="32"/>
        <source>take a line&apos;s or a fill&apos;s colour for the pen</source>
        <translation>die Farbe einer Linie oder Füllung für den Stift aufnehmen</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_eyedropper.cpp" line="63"/>
        <source>Nothing here to take a colour from: click a line or a fill.</source>
        <translation>Hier gibt es keine Farbe aufzunehmen: Klicken Sie auf eine Linie oder eine Füllung.</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_eyedropper.cpp" line="70"/>
        <source>The pen takes the line&apos;s colour %1.</source>
        <translation>Der Stift übernimmt die Farbe %1 der Linie.</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_eyedropper.cpp" line="71"/>
        <source>The pen takes the fill&apos;s colour %1.</source>
        <translation>Der Stift übernimmt die Farbe %1 der Füllung.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::FillTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/fill/tool_fill.h" line="23"/>
        <source>Fill</source>
        <translation>Füllen</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/fill/tool_fill.h" line="24"/>
        <source>fill an enclosed region with colour</source>
        <translation>einen geschlossenen Bereich mit Farbe füllen</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/tool_fill.cpp" line="70"/>
        <source>No closed region here: close the outline, or raise Close gaps</source>
        <translation>Hier ist kein geschlossener Bereich: Umriss schließen oder „Lücken schließen“ erhöhen</translation>
    </message>
</context>
<context>
    <name>finbook::ui::FrameActions</name>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="13"/>
        <source>Insert Frame &amp;Before</source>
        <translation>Einzelbild &amp;davor einfügen</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="15"/>
        <source>&amp;Insert Frame After</source>
        <translation>Einzelbild da&amp;nach einfügen</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="17"/>
        <source>&amp;Duplicate Frame</source>
        <translation>Einzelbild d&amp;uplizieren</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="19"/>
        <source>Generate In-be&amp;tweens…</source>
        <translation>&amp;Zwischenbilder erzeugen…</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="21"/>
        <source>Delete Fra&amp;me</source>
        <translation>Einzelbild &amp;löschen</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="24"/>
        <source>Move Frame &amp;Left</source>
        <translation>Einzelbild nach l&amp;inks verschieben</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="26"/>
        <source>Move Frame &amp;Right</source>
        <translation>Einzelbild nach &amp;rechts verschieben</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="29"/>
        <source>Hold Lon&amp;ger</source>
        <translation>Län&amp;ger halten</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="31"/>
        <source>Hold &amp;Shorter</source>
        <translation>&amp;Kürzer halten</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="34"/>
        <source>&amp;Previous Frame</source>
        <translation>&amp;Vorheriges Einzelbild</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="37"/>
        <source>&amp;Next Frame</source>
        <translation>Nä&amp;chstes Einzelbild</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/timeline/frame_actions.cpp" line="126"/>
        <source>Delete %n Frame(s)</source>
        <translation>
            <numerusform>%n Bild löschen</numerusform>
            <numerusform>%n Bilder löschen</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::ui::HandTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_hand.h" line="17"/>
        <source>Hand</source>
        <translation>Hand</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_hand.h" line="18"/>
        <source>drag the view</source>
        <translation>die Ansicht verschieben</translation>
    </message>
</context>
<context>
    <name>finbook::ui::InbetweenDialog</name>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="63"/>
        <source>Generate In-betweens</source>
        <translation>Zwischenbilder erzeugen</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="69"/>
        <source>Objects:</source>
        <translation>Objekte:</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="72"/>
        <source>Where the first drawing lands on the second (drag to pin):</source>
        <translation>Wo die erste Zeichnung auf der zweiten landet (ziehen zum Anpinnen):</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="199"/>
        <source>With these pins the drawings could not be fitted: %1</source>
        <translation>Mit diesen Pins ließen sich die Zeichnungen nicht anpassen: %1</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="246"/>
        <source>&amp;Frames between the keys:</source>
        <translation>&amp;Einzelbilder zwischen den Schlüsselbildern:</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="249"/>
        <source>Linear</source>
        <translation>Linear</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="250"/>
        <source>Ease in (slow from the first key)</source>
        <translation>Ease-in (langsam vom ersten Schlüsselbild weg)</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="251"/>
        <source>Ease out (slow into the second key)</source>
        <translation>Ease-out (langsam ins zweite Schlüsselbild hinein)</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="252"/>
        <source>Ease in and out</source>
        <translation>Ease-in und Ease-out</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="253"/>
        <source>Favour…</source>
        <translation>Gewichtet…</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="254"/>
        <source>&amp;Spacing:</source>
        <translation>&amp;Verteilung:</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="258"/>
        <source>Left favours the first key, right the second.</source>
        <translation>Links wird das erste Schlüsselbild bevorzugt, rechts das zweite.</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="259"/>
        <source>F&amp;avour:</source>
        <translation>&amp;Gewichtung:</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="262"/>
        <source>Move pins and cage corners along &amp;arcs</source>
        <translation>Pins und Käfigecken auf &amp;Bögen bewegen</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="265"/>
        <source>A limb swung between the keys keeps its length. Unchecked, every target moves in a straight line.</source>
        <translation>Ein zwischen den Schlüsselbildern geschwungenes Glied behält seine Länge. Ohne diese Option bewegt sich jeder Zielpunkt geradlinig.</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="268"/>
        <source>Carry &amp;different drawings onto each other</source>
        <translation>&amp;Verschiedene Zeichnungen ineinander überführen</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="272"/>
        <source>Where the two keys are separate drawings of an object, the first is fitted onto the second as rigidly as possible and carried there, fading into the second&apos;s lines at the end. Unchecked, the drawing switches over half way.</source>
        <translation>Wo die beiden Schlüsselbilder getrennte Zeichnungen eines Objekts sind, wird die erste so starr wie möglich an die zweite angepasst und dorthin getragen und geht am Ende in deren Linien über. Ohne Haken wechselt die Zeichnung auf halbem Weg.</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="424"/>
        <source>Making the in-betweens…</source>
        <translation>Die Zwischenbilder werden erstellt …</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="138"/>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="303"/>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="344"/>
        <source>(unnamed)</source>
        <translation>(unbenannt)</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="39"/>
        <source>Move Correspondence Pins</source>
        <translation>Zuordnungspins verschieben</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="306"/>
        <source>%1: interpolated</source>
        <translation>%1: interpoliert</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="308"/>
        <source>%1: held from the first key (no pins, cage or skeleton)</source>
        <translation>%1: vom ersten Schlüsselbild gehalten (keine Pins, kein Käfig und kein Skelett)</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="310"/>
        <source>%1: held from the first key (its pins, cage or skeleton differ between the keys)</source>
        <translation>%1: vom ersten Schlüsselbild gehalten (Pins, Käfig oder Skelett unterscheiden sich zwischen den Schlüsselbildern)</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="314"/>
        <source>%1: only in the first key, held in the first half</source>
        <translation>%1: nur im ersten Schlüsselbild, in der ersten Hälfte gehalten</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="316"/>
        <source>%1: only in the second key, held in the second half</source>
        <translation>%1: nur im zweiten Schlüsselbild, in der zweiten Hälfte gehalten</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="318"/>
        <source>%1: carried from the first key&apos;s drawing to the second&apos;s</source>
        <translation>%1: von der Zeichnung des ersten Schlüsselbilds zu der des zweiten getragen</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="328"/>
        <source>Select two different frames as keys.</source>
        <translation>Wählen Sie zwei verschiedene Einzelbilder als Schlüsselbilder aus.</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="341"/>
        <source>%1: could not be carried onto the second key&apos;s drawing, so it switches over half way. %2</source>
        <translation>%1: ließ sich nicht auf die Zeichnung des zweiten Schlüsselbilds tragen und wechselt daher auf halbem Weg. %2</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="180"/>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="347"/>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="393"/>
        <source>Fitting the drawings that differ…</source>
        <translation>Die verschiedenen Zeichnungen werden angepasst …</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="348"/>
        <source>Posing the preview…</source>
        <translation>Die Vorschau wird berechnet…</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="389"/>
        <source>The preview could not be posed: %1</source>
        <translation>Die Vorschau konnte nicht posiert werden: %1</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="395"/>
        <source>No object has matching pins or a matching cage in both keys: the in-betweens will only hold drawings.</source>
        <translation>Kein Objekt hat in beiden Schlüsselbildern passende Pins oder einen passenden Käfig: Die Zwischenbilder halten nur die Zeichnungen.</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="397"/>
        <source>The canvas shows the middle in-between.</source>
        <translation>Die Leinwand zeigt das mittlere Zwischenbild.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::LayerActions</name>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="15"/>
        <source>Layer %1</source>
        <translation>Ebene %1</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="32"/>
        <source>&amp;New Layer</source>
        <translation>&amp;Neue Ebene</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="39"/>
        <source>&amp;Duplicate Layer</source>
        <translation>Ebene &amp;duplizieren</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="46"/>
        <source>De&amp;lete Layer</source>
        <translation>Ebene &amp;löschen</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="57"/>
        <source>Move Layer &amp;Up</source>
        <translation>Ebene nach &amp;oben</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="59"/>
        <source>Move Layer D&amp;own</source>
        <translation>Ebene nach &amp;unten</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="66"/>
        <source>Layer &amp;Above</source>
        <translation>Ebene da&amp;rüber</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="68"/>
        <source>Layer &amp;Below</source>
        <translation>Ebene darun&amp;ter</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="71"/>
        <source>&amp;Show Layer</source>
        <translation>Ebene &amp;anzeigen</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="74"/>
        <source>Loc&amp;k Layer</source>
        <translation>Ebene &amp;sperren</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="77"/>
        <source>Layer &amp;Properties...</source>
        <translation>Ebenen&amp;eigenschaften...</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="81"/>
        <source>&amp;Insert Time</source>
        <translation>Zeit e&amp;infügen</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="83"/>
        <source>Delete &amp;Time</source>
        <translation>&amp;Zeit löschen</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="121"/>
        <location filename="../ui/src/layers/layer_sheet.cpp" line="398"/>
        <source>Lock Layer</source>
        <translation>Ebene sperren</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="121"/>
        <location filename="../ui/src/layers/layer_sheet.cpp" line="398"/>
        <source>Unlock Layer</source>
        <translation>Ebene entsperren</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="122"/>
        <location filename="../ui/src/layers/layer_sheet.cpp" line="393"/>
        <source>Show Layer</source>
        <translation>Ebene einblenden</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="122"/>
        <location filename="../ui/src/layers/layer_sheet.cpp" line="393"/>
        <source>Hide Layer</source>
        <translation>Ebene ausblenden</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="134"/>
        <source>Change Layer Properties</source>
        <translation>Ebeneneigenschaften ändern</translation>
    </message>
</context>
<context>
    <name>finbook::ui::LayerPropertiesDialog</name>
    <message>
        <location filename="../ui/src/layers/layer_properties_dialog.cpp" line="21"/>
        <source>Show its neighbouring drawings in the onion skin</source>
        <translation>Die benachbarten Zeichnungen in der Zwiebelhaut zeigen</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_properties_dialog.cpp" line="23"/>
        <source>Layer Properties</source>
        <translation>Ebeneneigenschaften</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_properties_dialog.cpp" line="36"/>
        <source>How far behind the page the layer lies: at depth 1 the camera&apos;s pans and zooms move it half as much (a distant background), at 0 exactly as much, below 0 more (a foreground rushing past).</source>
        <translation>Wie weit die Ebene hinter dem Blatt liegt: Bei Tiefe 1 bewegen Schwenks und Zooms der Kamera sie halb so stark (ein ferner Hintergrund), bei 0 genau so stark, unter 0 stärker (ein vorbeirauschender Vordergrund).</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_properties_dialog.cpp" line="42"/>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_properties_dialog.cpp" line="43"/>
        <source>&amp;Opacity:</source>
        <translation>&amp;Deckkraft:</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_properties_dialog.cpp" line="44"/>
        <source>&amp;Depth:</source>
        <translation>&amp;Tiefe:</translation>
    </message>
</context>
<context>
    <name>finbook::ui::LipSyncDialog</name>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="67"/>
        <source>&amp;Run</source>
        <translation>&amp;Starten</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="68"/>
        <source>&amp;Import Timings...</source>
        <translation>Zeiten &amp;importieren…</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="73"/>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="241"/>
        <source>Lip Sync</source>
        <translation>Lippensynchronisation</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="76"/>
        <source>Optional: the words spoken, for a closer fit</source>
        <translation>Optional: die gesprochenen Worte, für eine genauere Anpassung</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="93"/>
        <source>%1 (from frame %2)</source>
        <translation>%1 (ab Bild %2)</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="97"/>
        <source>Recognises English speech (PocketSphinx, US English). Other languages: import timings made elsewhere.</source>
        <translation>Erkennt englische Sprache (PocketSphinx, US-Englisch). Andere Sprachen: anderswo erstellte Zeiten importieren.</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="99"/>
        <source>The speech models are not installed (Debian: pocketsphinx-en-us): the mouth follows the loudness only, closed, half open or open.</source>
        <translation>Die Sprachmodelle sind nicht installiert (Debian: pocketsphinx-en-us): Der Mund folgt nur der Lautstärke, geschlossen, halb offen oder offen.</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="103"/>
        <source>Mouth:</source>
        <translation>Mund:</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="104"/>
        <source>%1 (%2 drawings)</source>
        <translation>%1 (%2 Zeichnungen)</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="105"/>
        <source>(none)</source>
        <translation>(keiner)</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="107"/>
        <source>&amp;Sound:</source>
        <translation>&amp;Ton:</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="108"/>
        <source>&amp;Dialogue:</source>
        <translation>&amp;Dialog:</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="120"/>
        <source>The animation has no sound: File &gt; Import Sound… first, or import timings made elsewhere.</source>
        <translation>Die Animation hat keinen Ton: zuerst Datei &gt; Ton importieren…, oder anderswo erstellte Zeiten importieren.</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="125"/>
        <source>Import Lip Sync Timings</source>
        <translation>Lippensynchron-Zeiten importieren</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="175"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="175"/>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="193"/>
        <source>Listening…</source>
        <translation>Hört zu…</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="211"/>
        <source>Cancelling…</source>
        <translation>Wird abgebrochen…</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="217"/>
        <source>Cancelled: nothing was changed.</source>
        <translation>Abgebrochen: Nichts wurde geändert.</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="221"/>
        <source>Nothing was changed.</source>
        <translation>Nichts wurde geändert.</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="224"/>
        <source>from the loudness (the speech models are not installed)</source>
        <translation>nach der Lautstärke (die Sprachmodelle sind nicht installiert)</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="225"/>
        <source>from the recognised speech</source>
        <translation>nach der erkannten Sprache</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="226"/>
        <source>from the speech and the dialogue</source>
        <translation>nach Sprache und Dialog</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="228"/>
        <source>spelt by rules, not found in the dictionary: %1</source>
        <translation>nach Regeln buchstabiert, nicht im Wörterbuch: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="246"/>
        <source>Keyed the mouth on %n frame(s), %1.</source>
        <translation>
            <numerusform>Mund auf %n Bild gesetzt, %1.</numerusform>
            <numerusform>Mund auf %n Bildern gesetzt, %1.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="248"/>
        <source>%n frame(s) of the mouth&apos;s layer hold no mouth and were left as they were.</source>
        <translation>
            <numerusform>%n Bild der Mund-Ebene enthält keinen Mund und blieb, wie es war.</numerusform>
            <numerusform>%n Bilder der Mund-Ebene enthalten keinen Mund und blieben, wie sie waren.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="262"/>
        <source>%1 was not imported: %2</source>
        <translation>%1 wurde nicht importiert: %2</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="268"/>
        <source>from %1</source>
        <translation>aus %1</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="316"/>
        <source>The clip holds no sound to follow.</source>
        <translation>Der Clip enthält keinen Ton, dem man folgen könnte.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::MainWindow</name>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="160"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="163"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="218"/>
        <source>Show Dr&amp;awing</source>
        <translation>Zeichnung anz&amp;eigen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="236"/>
        <source>Timeline</source>
        <translation>Zeitleiste</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="239"/>
        <source>Objects</source>
        <translation>Objekte</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="243"/>
        <source>Reference</source>
        <translation>Referenz</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="263"/>
        <source>&lt;opened document&gt;</source>
        <translation>&lt;geöffnetes Dokument&gt;</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="265"/>
        <source>Undo History</source>
        <translation>Verlauf</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="272"/>
        <source>Palette</source>
        <translation>Palette</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="298"/>
        <source>Rotation </source>
        <translation>Drehung </translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="302"/>
        <source>The view&apos;s rotation: the drawing is not changed. Shift+Space-drag on the canvas turns it freely; 4 and 6 turn it by 15°, 5 resets it, Shift+M mirrors it.</source>
        <translation>Die Drehung der Ansicht: die Zeichnung bleibt unverändert. Umschalt+Leertaste-Ziehen auf der Leinwand dreht sie frei; 4 und 6 drehen um 15°, 5 setzt zurück, Umschalt+M spiegelt.</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="328"/>
        <source>The reference &quot;%1&quot; cannot be shown: %2</source>
        <translation>Die Referenz „%1“ kann nicht angezeigt werden: %2</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="337"/>
        <source>%1, %2 px</source>
        <translation>%1, %2 px</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="348"/>
        <source>Frame %1 / %2</source>
        <translation>Einzelbild %1 / %2</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="349"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="354"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="436"/>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="355"/>
        <source>%1[*] - Finbook</source>
        <translation>%1[*] – Finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="38"/>
        <source>Finbook animations (*.finbook);;All files (*)</source>
        <translation>Finbook-Animationen (*.finbook);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="49"/>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="84"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="139"/>
        <source>Cannot Open File</source>
        <translation>Datei kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="174"/>
        <source>Cannot Save File</source>
        <translation>Datei kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="180"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/window/main_window_files.cpp" line="146"/>
        <source>Opened what was readable of %1 (%n problem(s) repaired); save it under a new name.</source>
        <translation>
            <numerusform>Lesbare Teile von %1 geöffnet (%n Problem behoben); speichern Sie die Animation unter einem neuen Namen.</numerusform>
            <numerusform>Lesbare Teile von %1 geöffnet (%n Probleme behoben); speichern Sie die Animation unter einem neuen Namen.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="102"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="107"/>
        <source>Cannot Open the Example</source>
        <translation>Das Beispiel lässt sich nicht öffnen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="112"/>
        <source>The example walk cycle: change it and save it as your own.</source>
        <translation>Der Beispiel-Laufzyklus: ändere ihn und speichere ihn als deinen eigenen.</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="230"/>
        <source>&amp;%1 %2</source>
        <translation>&amp;%1 %2</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="239"/>
        <source>No recent files</source>
        <translation>Keine zuletzt geöffneten Dateien</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="249"/>
        <source>Cannot Import Mesh</source>
        <translation>Netz kann nicht importiert werden</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="253"/>
        <location filename="../ui/src/window/main_window_menus.cpp" line="117"/>
        <source>Import Mesh</source>
        <translation>Netz importieren</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="373"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="386"/>
        <source>Reading &quot;%1&quot;...</source>
        <translation>„%1“ wird gelesen …</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="357"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="373"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="386"/>
        <location filename="../ui/src/window/main_window_menus.cpp" line="125"/>
        <source>Import Picture</source>
        <translation>Bild importieren</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="337"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="375"/>
        <source>Cannot Import Picture</source>
        <translation>Bild kann nicht importiert werden</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="358"/>
        <source>&quot;%1&quot; stands on a flat background (%2). Make that colour transparent, so that the object is only what is drawn on it?</source>
        <translation>„%1“ steht auf einem einfarbigen Hintergrund (%2). Diese Farbe durchsichtig machen, damit das Objekt nur aus dem besteht, was darauf gezeichnet ist?</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/window/main_window_files.cpp" line="388"/>
        <source>Imported &quot;%1&quot;: %n picture object(s).</source>
        <translation>
            <numerusform>„%1“ importiert: %n Bildobjekt.</numerusform>
            <numerusform>„%1“ importiert: %n Bildobjekte.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="398"/>
        <source>Pasted picture</source>
        <translation>Eingefügtes Bild</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="410"/>
        <source>Reading the pasted picture...</source>
        <translation>Das eingefügte Bild wird gelesen...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="411"/>
        <source>Pasted a picture as an object.</source>
        <translation>Ein Bild wurde als Objekt eingefügt.</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="424"/>
        <source>Damaged File</source>
        <translation>Beschädigte Datei</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="425"/>
        <source>Open anyway shows what is still readable as a new, unsaved animation; the damaged file is not changed.</source>
        <translation>„Trotzdem öffnen“ zeigt den noch lesbaren Inhalt als neue, ungespeicherte Animation an; die beschädigte Datei wird nicht verändert.</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="428"/>
        <source>Open Anyway</source>
        <translation>Trotzdem öffnen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="438"/>
        <source>Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="439"/>
        <source>&quot;%1&quot; has changes that are not saved. Save them before going on?</source>
        <translation>„%1“ hat ungespeicherte Änderungen. Vorher speichern?</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="445"/>
        <source>Open Animation</source>
        <translation>Animation öffnen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="451"/>
        <source>Save Animation</source>
        <translation>Animation speichern</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="452"/>
        <source>untitled.finbook</source>
        <translation>unbenannt.finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="65"/>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="77"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="78"/>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="80"/>
        <source>&amp;Open...</source>
        <translation>Ö&amp;ffnen...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="82"/>
        <source>Open Exa&amp;mple</source>
        <translation>Beis&amp;piel öffnen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="84"/>
        <source>&amp;Welcome...</source>
        <translation>&amp;Willkommen...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="91"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="95"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="97"/>
        <source>Save &amp;As...</source>
        <translation>Speichern &amp;unter...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="101"/>
        <source>E&amp;xport...</source>
        <translation>E&amp;xportieren...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="114"/>
        <source>&amp;Import Mesh...</source>
        <translation>Netz &amp;importieren...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="117"/>
        <source>OFF meshes (*.off)</source>
        <translation>OFF-Netze (*.off)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="122"/>
        <source>Import &amp;Picture...</source>
        <translation>Bil&amp;d importieren...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="126"/>
        <source>Pictures (*.png *.jpg *.jpeg *.webp *.tif *.tiff *.gif *.bmp *.ora);;OpenRaster stacks (*.ora);;All files (*)</source>
        <translation>Bilder (*.png *.jpg *.jpeg *.webp *.tif *.tiff *.gif *.bmp *.ora);;OpenRaster-Stapel (*.ora);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="132"/>
        <source>Import Re&amp;ference...</source>
        <translation>&amp;Referenz importieren...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="138"/>
        <source>Cannot Import Reference</source>
        <translation>Referenz kann nicht importiert werden</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="140"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="158"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="160"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="164"/>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="410"/>
        <location filename="../ui/src/window/main_window_menus.cpp" line="174"/>
        <source>Paste</source>
        <translation>Einfügen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="179"/>
        <source>Cu&amp;t</source>
        <translation>&amp;Ausschneiden</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="186"/>
        <source>&amp;Copy</source>
        <translation>&amp;Kopieren</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="193"/>
        <source>&amp;Paste</source>
        <translation>&amp;Einfügen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="215"/>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="222"/>
        <source>Select &amp;All</source>
        <translation>Alles a&amp;uswählen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="228"/>
        <source>Dese&amp;lect</source>
        <translation>Auswahl au&amp;fheben</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="235"/>
        <source>D&amp;ocument Settings...</source>
        <translation>D&amp;okumenteinstellungen...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="238"/>
        <source>Pre&amp;ferences...</source>
        <translation>Ein&amp;stellungen...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="267"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="268"/>
        <source>Zoom &amp;In</source>
        <translation>Ver&amp;größern</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="270"/>
        <source>Zoom &amp;Out</source>
        <translation>Ver&amp;kleinern</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="272"/>
        <source>&amp;Fit to Window</source>
        <translation>An &amp;Fenster anpassen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="274"/>
        <source>&amp;Actual Size (100 %)</source>
        <translation>&amp;Originalgröße (100 %)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="280"/>
        <source>Rotate View &amp;Left</source>
        <translation>Ansicht nach &amp;links drehen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="282"/>
        <source>Rotate View &amp;Right</source>
        <translation>Ansicht nach &amp;rechts drehen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="285"/>
        <source>R&amp;eset View Rotation</source>
        <translation>Dre&amp;hung der Ansicht zurücksetzen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="288"/>
        <source>Mirror Vie&amp;w</source>
        <translation>Ansicht sp&amp;iegeln</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="296"/>
        <source>O&amp;nion Skin</source>
        <translation>&amp;Zwiebelhaut</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="307"/>
        <source>Onion Skin &amp;Settings...</source>
        <translation>Zwiebelhaut-&amp;Einstellungen...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="309"/>
        <source>Show &amp;Mesh</source>
        <translation>&amp;Netz anzeigen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="315"/>
        <source>&amp;Camera View</source>
        <translation>Kamera&amp;ansicht</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="321"/>
        <source>&amp;Dim Other Layers</source>
        <translation>Andere Ebenen ab&amp;dunkeln</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="328"/>
        <source>&amp;Panels</source>
        <translation>&amp;Bedienfelder</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="334"/>
        <source>F&amp;rame</source>
        <translation>&amp;Einzelbild</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="347"/>
        <source>&amp;Layer</source>
        <translation>Ebe&amp;ne</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="354"/>
        <source>&amp;Object</source>
        <translation>&amp;Objekt</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="372"/>
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="375"/>
        <source>Tools</source>
        <translation>Werkzeuge</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="383"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="385"/>
        <source>Finbook &amp;Manual</source>
        <translation>Finbook-&amp;Handbuch</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="390"/>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>&amp;Tastenkürzel</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="392"/>
        <source>&amp;About Finbook</source>
        <translation>Ü&amp;ber Finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="422"/>
        <source>Onion Skin</source>
        <translation>Zwiebelhaut</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="446"/>
        <source>About Finbook</source>
        <translation>Über Finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="447"/>
        <source>&lt;h3&gt;Finbook %1&lt;/h3&gt;&lt;p&gt;A flipbook animation editor: draw frame by frame, and bend drawings with pins.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Finbook %1&lt;/h3&gt;&lt;p&gt;Ein Daumenkino-Animationseditor: Einzelbilder nacheinander zeichnen und Zeichnungen mit Pins verformen.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_deform.cpp" line="36"/>
        <source>&amp;Deform</source>
        <translation>&amp;Verformen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_deform.cpp" line="51"/>
        <source>&amp;Lip Sync...</source>
        <translation>&amp;Lippensynchronisation…</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_deform.cpp" line="52"/>
        <source>Key a mouth chart&apos;s drawings from the soundtrack</source>
        <translation>Die Zeichnungen einer Mundtabelle nach der Tonspur setzen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_deform.cpp" line="74"/>
        <source>Preparing the deformation…</source>
        <translation>Verformung wird vorbereitet…</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="162"/>
        <location filename="../ui/src/window/main_window_toolbars.cpp" line="39"/>
        <source>Undo</source>
        <translation>Rückgängig</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="166"/>
        <location filename="../ui/src/window/main_window_toolbars.cpp" line="41"/>
        <source>Redo</source>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_toolbars.cpp" line="45"/>
        <source>Apply Pose</source>
        <translation>Pose anwenden</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_toolbars.cpp" line="47"/>
        <source>Remove Rig</source>
        <translation>Rig entfernen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_toolbars.cpp" line="49"/>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_toolbars.cpp" line="51"/>
        <source>Shape</source>
        <translation>Form</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="30"/>
        <source>Reset &amp;Bone Pose</source>
        <translation>K&amp;nochenpose zurücksetzen</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="31"/>
        <source>Turn the bone selected with the Bone tool back to rest; the bones below it keep their bends</source>
        <translation>Den mit dem Knochenwerkzeug gewählten Knochen in die Ruhelage zurückdrehen; die Knochen darunter behalten ihre Beugung</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="35"/>
        <source>&amp;Edit Joints</source>
        <translation>&amp;Gelenke bearbeiten</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="37"/>
        <source>With the Bone tool, move, insert and delete the joints of an unposed skeleton instead of posing it</source>
        <translation>Mit dem Knochenwerkzeug die Gelenke eines unverformten Skeletts verschieben, einfügen und löschen, statt es zu posieren</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="58"/>
        <source>Show S&amp;keleton</source>
        <translation>&amp;Skelett anzeigen</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="64"/>
        <source>Skeleton</source>
        <translation>Skelett</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="72"/>
        <source>S&amp;kinning</source>
        <translation>S&amp;kinning</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="79"/>
        <source>&amp;Rigid (Bones Pin the Mesh)</source>
        <translation>&amp;Starr (Knochen fixieren das Netz)</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="81"/>
        <source>&amp;Linear Blend</source>
        <translation>&amp;Lineare Überblendung</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="83"/>
        <source>&amp;Cut-out (Limbs Turn over the Body)</source>
        <translation>&amp;Ausschneidefigur (Glieder drehen sich über dem Körper)</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="115"/>
        <source>Rigid</source>
        <translation>Starr</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="115"/>
        <source>Blend</source>
        <translation>Mischen</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="115"/>
        <source>Cut-out</source>
        <translation>Ausschnitt</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/main_window_recovery.cpp" line="63"/>
        <source>Cannot Recover</source>
        <translation>Wiederherstellung nicht möglich</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/main_window_recovery.cpp" line="72"/>
        <source>Recovered %1 as it was at %2; save it to keep it.</source>
        <translation>%1 mit dem Stand vom %2 wiederhergestellt; speichern Sie die Animation, um sie zu behalten.</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/close_gap_box.cpp" line="27"/>
        <location filename="../ui/src/fill/close_gap_box.cpp" line="35"/>
        <source>Close gaps: automatic</source>
        <translation>Lücken schließen: automatisch</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/close_gap_box.cpp" line="34"/>
        <source>Close gaps: automatic (%1 px)</source>
        <translation>Lücken schließen: automatisch (%1 px)</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="41"/>
        <source>Close gaps up to </source>
        <translation>Lücken schließen bis </translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="42"/>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="43"/>
        <source>Openings in an outline up to this wide still make a region the Fill tool can fill (0 = only closed outlines)</source>
        <translation>Öffnungen im Umriss bis zu dieser Breite ergeben noch einen Bereich, den das Füllwerkzeug füllen kann (0 = nur geschlossene Umrisse)</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="88"/>
        <source>Fill All Enclosed Re&amp;gions</source>
        <translation>Alle geschlossenen Bereiche &amp;füllen</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="90"/>
        <source>Fill every closed region of the current object that has no fill, in the pen colour</source>
        <translation>Jeden geschlossenen Bereich des aktuellen Objekts ohne Füllung in der Stiftfarbe füllen</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="97"/>
        <source>The current object has no unfilled closed region</source>
        <translation>Das aktuelle Objekt hat keinen ungefüllten geschlossenen Bereich</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="109"/>
        <source>The colour the Fill tool fills with (the pen&apos;s)</source>
        <translation>Die Farbe, mit der das Füllwerkzeug füllt (die des Stifts)</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/main_window_shade.cpp" line="33"/>
        <source>Shading</source>
        <translation>Schattierung</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/main_window_lipsync.cpp" line="15"/>
        <source>Lip Sync</source>
        <translation>Lippensynchronisation</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/main_window_lipsync.cpp" line="16"/>
        <source>Lip sync keys the drawings of a mouth chart. Make one with Object &gt; New Mouth Chart, redraw its mouths in your style, then come back here.</source>
        <translation>Die Lippensynchronisation setzt die Zeichnungen einer Mundtabelle. Legen Sie eine mit Objekt &gt; Neue Mundtabelle an, zeichnen Sie die Münder in Ihrem Stil neu und kommen Sie dann hierher zurück.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ManualBrowser</name>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="30"/>
        <location filename="../ui/src/help/manual_browser.cpp" line="99"/>
        <source>Contents</source>
        <translation>Inhalt</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="31"/>
        <source>Getting Started: Draw, Bend, Play</source>
        <translation>Erste Schritte: zeichnen, biegen, abspielen</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="32"/>
        <source>Drawing and the View</source>
        <translation>Zeichnen und die Ansicht</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="33"/>
        <source>Fills and Shading</source>
        <translation>Füllungen und Schattierung</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="34"/>
        <source>Pins</source>
        <translation>Pins</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="35"/>
        <source>Cages</source>
        <translation>Käfige</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="36"/>
        <source>Bones and Skeletons</source>
        <translation>Knochen und Skelette</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="37"/>
        <source>In-betweens</source>
        <translation>Zwischenbilder</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="38"/>
        <source>Timeline, Layers and Sound</source>
        <translation>Zeitleiste, Ebenen und Ton</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="39"/>
        <source>Swapping Drawings and Lip Sync</source>
        <translation>Zeichnungen austauschen und Lippensynchronisation</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="40"/>
        <source>Camera</source>
        <translation>Kamera</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="41"/>
        <source>Pictures as Objects</source>
        <translation>Bilder als Objekte</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="42"/>
        <source>Reference Pictures and Video</source>
        <translation>Referenzbilder und -videos</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="43"/>
        <source>Exporting</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="44"/>
        <source>Saving, Autosave and Recovery</source>
        <translation>Speichern, automatisches Speichern und Wiederherstellen</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="45"/>
        <source>The Command Line</source>
        <translation>Die Befehlszeile</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="46"/>
        <source>Keyboard Shortcuts</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="47"/>
        <source>Installing</source>
        <translation>Installieren</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="84"/>
        <source>Finbook Manual</source>
        <translation>Finbook-Handbuch</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="97"/>
        <source>Back</source>
        <translation>Zurück</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="98"/>
        <source>Forward</source>
        <translation>Vor</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="104"/>
        <source>Search the manual</source>
        <translation>Im Handbuch suchen</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ObjectActions</name>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="28"/>
        <source>&amp;New Object</source>
        <translation>&amp;Neues Objekt</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="30"/>
        <source>&amp;Delete Object</source>
        <translation>Objekt &amp;löschen</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="31"/>
        <source>&amp;Merge Objects</source>
        <translation>Objekte &amp;zusammenführen</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="34"/>
        <source>Move &amp;Selection to Object</source>
        <translation>&amp;Auswahl in Objekt verschieben</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="35"/>
        <source>Bring &amp;Forward</source>
        <translation>Nach &amp;vorne bringen</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="37"/>
        <source>Send &amp;Backward</source>
        <translation>Nach &amp;hinten stellen</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="39"/>
        <source>&amp;Visible</source>
        <translation>&amp;Sichtbar</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="40"/>
        <source>&amp;Locked</source>
        <translation>&amp;Gesperrt</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="43"/>
        <source>New object above the current one</source>
        <translation>Neues Objekt über dem aktuellen</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="44"/>
        <source>Merge the selected objects, or the current one into the one below</source>
        <translation>Die ausgewählten Objekte zusammenführen oder das aktuelle mit dem darunterliegenden</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="45"/>
        <source>Move the selected strokes to another object</source>
        <translation>Die ausgewählten Striche in ein anderes Objekt verschieben</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="47"/>
        <source>New</source>
        <translation>Neu</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="48"/>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="49"/>
        <source>Merge</source>
        <translation>Zusammenführen</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="50"/>
        <source>Move To</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="119"/>
        <source>Object %1</source>
        <translation>Objekt %1</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="178"/>
        <source>Merge Objects</source>
        <translation>Objekte zusammenführen</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="200"/>
        <source>Move Strokes to Object</source>
        <translation>Striche in Objekt verschieben</translation>
    </message>
</context>
<context>
    <name>finbook::ui::OnionSkinEditor</name>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="14"/>
        <source>Show onion skin</source>
        <translation>Zwiebelhaut anzeigen</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="24"/>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="27"/>
        <source>Frames before:</source>
        <translation>Einzelbilder davor:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="28"/>
        <source>Frames after:</source>
        <translation>Einzelbilder danach:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="29"/>
        <source>Opacity of the nearest frame:</source>
        <translation>Deckkraft des nächsten Einzelbilds:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="30"/>
        <source>Tint before:</source>
        <translation>Tönung davor:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="31"/>
        <source>Tint after:</source>
        <translation>Tönung danach:</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PalettePanel</name>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="44"/>
        <source>&quot;%1&quot; is not a palette Finbook can read: %2.</source>
        <translation>&quot;%1&quot; ist keine Palette, die Finbook lesen kann: %2.</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="72"/>
        <source>Swatch name</source>
        <translation>Name des Farbfelds</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="73"/>
        <source>The chosen swatch&apos;s name: type and press Return to rename it</source>
        <translation>Der Name des gewählten Farbfelds: eingeben und Eingabe drücken, um es umzubenennen</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="89"/>
        <source>Add the pen&apos;s colour to the palette</source>
        <translation>Die Stiftfarbe zur Palette hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="90"/>
        <source>Set</source>
        <translation>Setzen</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="91"/>
        <source>Give the chosen swatch the pen&apos;s colour</source>
        <translation>Dem gewählten Farbfeld die Stiftfarbe geben</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="93"/>
        <source>Move the chosen swatch one place earlier</source>
        <translation>Das gewählte Farbfeld eine Stelle nach vorn</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="95"/>
        <source>Move the chosen swatch one place later</source>
        <translation>Das gewählte Farbfeld eine Stelle nach hinten</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="97"/>
        <source>Delete the chosen swatch from the palette</source>
        <translation>Das gewählte Farbfeld aus der Palette löschen</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="99"/>
        <source>Import, export, save and load palettes</source>
        <translation>Paletten importieren, exportieren, speichern und laden</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="102"/>
        <source>&amp;Import GIMP Palette...</source>
        <translation>GIMP-Palette &amp;importieren...</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="103"/>
        <source>&amp;Export GIMP Palette...</source>
        <translation>GIMP-Palette &amp;exportieren...</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="105"/>
        <source>&amp;Save as User Palette...</source>
        <translation>Als Benutzerpalette &amp;speichern...</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="106"/>
        <source>&amp;Load User Palette</source>
        <translation>Benutzerpalette &amp;laden</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="109"/>
        <source>&amp;Reset to Finbook&apos;s Colours</source>
        <translation>Auf Finbooks Farben &amp;zurücksetzen</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="110"/>
        <source>Reset Palette</source>
        <translation>Palette zurücksetzen</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="192"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="214"/>
        <source>A palette holds at most %1 colours.</source>
        <translation>Eine Palette fasst höchstens %1 Farben.</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="219"/>
        <source>Add Swatch</source>
        <translation>Farbfeld hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="230"/>
        <source>Recolour Swatch</source>
        <translation>Farbfeld umfärben</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="240"/>
        <source>Delete Swatch</source>
        <translation>Farbfeld löschen</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="251"/>
        <location filename="../ui/src/palette/palette_panel.cpp" line="288"/>
        <source>Move Swatch</source>
        <translation>Farbfeld verschieben</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="262"/>
        <source>Rename Swatch</source>
        <translation>Farbfeld umbenennen</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="338"/>
        <source>it is far larger than a palette</source>
        <translation>sie ist weit größer als eine Palette</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="347"/>
        <location filename="../ui/src/palette/palette_panel.cpp" line="410"/>
        <source>Import Palette</source>
        <translation>Palette importieren</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="354"/>
        <location filename="../ui/src/palette/palette_panel.cpp" line="376"/>
        <source>The palette could not be saved as &quot;%1&quot;: %2</source>
        <translation>Die Palette konnte nicht als &quot;%1&quot; gespeichert werden: %2</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="368"/>
        <source>A user palette needs a name.</source>
        <translation>Eine Benutzerpalette braucht einen Namen.</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="370"/>
        <source>The folder for user palettes (%1) could not be made.</source>
        <translation>Der Ordner für Benutzerpaletten (%1) konnte nicht angelegt werden.</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="391"/>
        <source>(no user palettes yet)</source>
        <translation>(noch keine Benutzerpaletten)</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="398"/>
        <source>Load Palette</source>
        <translation>Palette laden</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="404"/>
        <source>Import GIMP Palette</source>
        <translation>GIMP-Palette importieren</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="405"/>
        <source>GIMP palettes (*.gpl);;All files (*)</source>
        <translation>GIMP-Paletten (*.gpl);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="415"/>
        <source>Export GIMP Palette</source>
        <translation>GIMP-Palette exportieren</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="417"/>
        <source>GIMP palettes (*.gpl)</source>
        <translation>GIMP-Paletten (*.gpl)</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="424"/>
        <source>Export Palette</source>
        <translation>Palette exportieren</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="426"/>
        <source>Palette saved as &quot;%1&quot;.</source>
        <translation>Palette als &quot;%1&quot; gespeichert.</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="433"/>
        <source>Save as User Palette</source>
        <translation>Als Benutzerpalette speichern</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="433"/>
        <source>Name of the palette:</source>
        <translation>Name der Palette:</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="439"/>
        <source>Save Palette</source>
        <translation>Palette speichern</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="441"/>
        <source>Saved as the user palette &quot;%1&quot;; Palette &gt; Load User Palette brings it into any drawing.</source>
        <translation>Als Benutzerpalette &quot;%1&quot; gespeichert; Palette &gt; Benutzerpalette laden bringt sie in jede Zeichnung.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PenTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_pen.h" line="40"/>
        <source>Pen</source>
        <translation>Stift</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_pen.h" line="43"/>
        <source>draw lines; the pen&apos;s pressure sets their width</source>
        <translation>Linien zeichnen; der Stiftdruck bestimmt ihre Breite</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_pen.cpp" line="117"/>
        <source>Draw Stroke</source>
        <translation>Strich zeichnen</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PinTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/pins/tool_pin.h" line="19"/>
        <source>Pin</source>
        <translation>Pin</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/pins/tool_pin.h" line="22"/>
        <source>pin points and drag them: the drawing bends as rigidly as it can</source>
        <translation>Punkte anheften und ziehen: Die Zeichnung biegt sich so starr wie möglich</translation>
    </message>
    <message>
        <location filename="../ui/src/pins/tool_pin.cpp" line="162"/>
        <source>Click on a visible, unlocked drawing to pin it.</source>
        <translation>Klicken Sie auf eine sichtbare, nicht gesperrte Zeichnung, um einen Pin zu setzen.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PlaybackController</name>
    <message>
        <location filename="../ui/src/timeline/playback_controller.cpp" line="61"/>
        <location filename="../ui/src/timeline/playback_controller.cpp" line="226"/>
        <source>Pl&amp;ay</source>
        <translation>Abs&amp;pielen</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/playback_controller.cpp" line="65"/>
        <source>Play or pause the animation</source>
        <translation>Animation abspielen oder anhalten</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/playback_controller.cpp" line="73"/>
        <source>L&amp;oop</source>
        <translation>&amp;Endlosschleife</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/playback_controller.cpp" line="77"/>
        <source>Start again at the end of the play range</source>
        <translation>Am Ende des Wiedergabebereichs wieder von vorn beginnen</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/playback_controller.cpp" line="226"/>
        <source>P&amp;ause</source>
        <translation>&amp;Pause</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PreferencesDialog</name>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="21"/>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="25"/>
        <source>New Documents</source>
        <translation>Neue Dokumente</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="26"/>
        <source>Onion Skin</source>
        <translation>Zwiebelhaut</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="27"/>
        <source>Keyboard Shortcuts</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="42"/>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="48"/>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="55"/>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="56"/>
        <source>Never</source>
        <translation>Nie</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="57"/>
        <source>How often Finbook keeps a recovery copy of unsaved changes, offered at the next start if Finbook did not close normally.</source>
        <translation>Wie oft Finbook eine Wiederherstellungskopie ungespeicherter Änderungen anlegt; sie wird beim nächsten Start angeboten, falls Finbook nicht normal beendet wurde.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="61"/>
        <source>Frame rate:</source>
        <translation>Bildrate:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="62"/>
        <source>Canvas width:</source>
        <translation>Leinwandbreite:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="63"/>
        <source>Canvas height:</source>
        <translation>Leinwandhöhe:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="64"/>
        <source>Autosave every:</source>
        <translation>Automatisch speichern alle:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="86"/>
        <source>Conflicting Shortcuts</source>
        <translation>Kollidierende Tastenkürzel</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="87"/>
        <source>Two or more actions share a shortcut. Change or clear the shortcuts marked in red, then press OK again.</source>
        <translation>Mehrere Aktionen teilen sich ein Tastenkürzel. Ändern oder löschen Sie die rot markierten Kürzel und drücken Sie erneut OK.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::RecoveryDialog</name>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="17"/>
        <source>Recover Unsaved Work</source>
        <translation>Ungespeicherte Arbeit wiederherstellen</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="18"/>
        <source>Finbook did not close normally last time. It kept these copies of work that was not saved:</source>
        <translation>Finbook wurde beim letzten Mal nicht normal beendet. Folgende Kopien ungespeicherter Arbeit wurden aufbewahrt:</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="31"/>
        <source>&amp;Restore</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="32"/>
        <source>&amp;Discard</source>
        <translation>&amp;Verwerfen</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="33"/>
        <source>&amp;Later</source>
        <translation>&amp;Später</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="35"/>
        <source>Open the copy as an unsaved animation</source>
        <translation>Die Kopie als ungespeicherte Animation öffnen</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="36"/>
        <source>Delete the copy for good</source>
        <translation>Die Kopie endgültig löschen</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="37"/>
        <source>Keep the copies and ask again at the next start</source>
        <translation>Die Kopien behalten und beim nächsten Start erneut fragen</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="56"/>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="58"/>
        <source>%1 — %2 — %n frame(s)</source>
        <translation>
            <numerusform>%1 — %2 — %n Einzelbild</numerusform>
            <numerusform>%1 — %2 — %n Einzelbilder</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::ui::ReferencePanel</name>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="39"/>
        <source>&amp;Visible</source>
        <translation>&amp;Sichtbar</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="40"/>
        <source>Loc&amp;ked</source>
        <translation>&amp;Gesperrt</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="43"/>
        <location filename="../ui/src/reference/reference_panel.cpp" line="44"/>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="45"/>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="46"/>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="47"/>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="48"/>
        <source>Document rate</source>
        <translation>Rate des Dokuments</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="108"/>
        <source>Picture rate:</source>
        <translation>Bildrate:</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="110"/>
        <source>Pictures per second of animation. At the document&apos;s rate every frame shows the next picture; a lower rate holds each picture for several frames.</source>
        <translation>Bilder pro Sekunde Animation. Bei der Rate des Dokuments zeigt jedes Frame das nächste Bild; eine niedrigere Rate hält jedes Bild für mehrere Frames.</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="112"/>
        <source>Animation frames per second of video. At the document&apos;s rate the video plays in real time; a higher rate plays it slower, spreading each second over more frames.</source>
        <translation>Animationsframes pro Sekunde Video. Bei der Rate des Dokuments läuft das Video in Echtzeit; eine höhere Rate spielt es langsamer ab und verteilt jede Sekunde auf mehr Frames.</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="51"/>
        <source>&amp;Remove Reference</source>
        <translation>Referenz &amp;entfernen</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="57"/>
        <source>Opacity:</source>
        <translation>Deckkraft:</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="58"/>
        <source>Centre X:</source>
        <translation>Mitte X:</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="59"/>
        <source>Centre Y:</source>
        <translation>Mitte Y:</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="60"/>
        <source>Scale:</source>
        <translation>Maßstab:</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="61"/>
        <source>Rotation:</source>
        <translation>Drehung:</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="108"/>
        <source>Video rate:</source>
        <translation>Videorate:</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="90"/>
        <source>No reference. File → Import Reference… puts a picture or a video under the drawing.</source>
        <translation>Keine Referenz. Datei → Referenz importieren… legt ein Bild oder Video unter die Zeichnung.</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="167"/>
        <source>The reference could not be placed on the canvas.</source>
        <translation>Die Referenz ließ sich nicht auf der Leinwand platzieren.</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="175"/>
        <location filename="../ui/src/reference/reference_panel.cpp" line="182"/>
        <source>Import Reference</source>
        <translation>Referenz importieren</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/reference/reference_panel.cpp" line="183"/>
        <source>“%1” is one of %n numbered pictures (%2 … %3). Import them all as a sequence, one picture per frame?</source>
        <translation>
            <numerusform>„%1“ ist eines von %n nummerierten Bildern (%2 … %3). Alle als Folge importieren, ein Bild pro Frame?</numerusform>
            <numerusform>„%1“ ist eines von %n nummerierten Bildern (%2 … %3). Alle als Folge importieren, ein Bild pro Frame?</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="196"/>
        <source>Pictures and videos (*.png *.jpg *.jpeg *.webp *.bmp *.gif *.tif *.tiff *.mp4 *.m4v *.mov *.mkv *.webm *.avi);;All files (*)</source>
        <translation>Bilder und Videos (*.png *.jpg *.jpeg *.webp *.bmp *.gif *.tif *.tiff *.mp4 *.m4v *.mov *.mkv *.webm *.avi);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ReferenceTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/reference/tool_reference.h" line="21"/>
        <source>Move Reference</source>
        <translation>Referenz verschieben</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/reference/tool_reference.h" line="24"/>
        <source>move, scale and turn the reference picture</source>
        <translation>das Referenzbild verschieben, skalieren und drehen</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SelectTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_select.h" line="28"/>
        <source>Select</source>
        <translation>Auswahl</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_select.h" line="31"/>
        <source>lasso lines, then move, turn or scale them</source>
        <translation>Linien mit dem Lasso wählen, dann verschieben, drehen oder skalieren</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="400"/>
        <source>The strokes cannot be transformed that far.</source>
        <translation>So weit lassen sich die Striche nicht umformen.</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="409"/>
        <source>Move Strokes</source>
        <translation>Striche verschieben</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="409"/>
        <source>Move Picture</source>
        <translation>Bild verschieben</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="410"/>
        <source>Rotate Strokes</source>
        <translation>Striche drehen</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="410"/>
        <source>Rotate Picture</source>
        <translation>Bild drehen</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="411"/>
        <source>Scale Strokes</source>
        <translation>Striche skalieren</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="411"/>
        <source>Scale Picture</source>
        <translation>Bild skalieren</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="418"/>
        <source>The picture cannot be transformed that far.</source>
        <translation>So weit lässt sich das Bild nicht umformen.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ShadingPanel</name>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="25"/>
        <source>Flat</source>
        <translation>Flach</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="26"/>
        <source>Cel, two tones</source>
        <translation>Cel, zwei Töne</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="27"/>
        <source>Cel, three tones</source>
        <translation>Cel, drei Töne</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="28"/>
        <source>Smooth</source>
        <translation>Weich</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="29"/>
        <source>Shade the current object&apos;s fills from its rounded shape, in every frame where the object appears (objects of the same name)</source>
        <translation>Die Füllungen des aktuellen Objekts nach seiner gerundeten Form schattieren, in jedem Bild, in dem das Objekt vorkommt (Objekte gleichen Namens)</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="31"/>
        <source>Fills:</source>
        <translation>Füllungen:</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="32"/>
        <source>Rim light</source>
        <translation>Randlicht</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="34"/>
        <source>A light edge on the side away from the light</source>
        <translation>Ein heller Rand auf der vom Licht abgewandten Seite</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="42"/>
        <source>Where the light comes from on screen: 0° from the right, 90° from above, 180° from the left</source>
        <translation>Woher das Licht auf dem Bildschirm kommt: 0° von rechts, 90° von oben, 180° von links</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="44"/>
        <source>Light direction:</source>
        <translation>Lichtrichtung:</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="50"/>
        <source>How high the light stands above the drawing: 0° grazes it, 90° shines from the viewer</source>
        <translation>Wie hoch das Licht über der Zeichnung steht: 0° streift sie, 90° scheint vom Betrachter her</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="52"/>
        <source>Light height:</source>
        <translation>Lichthöhe:</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="89"/>
        <source>Fill regions of the current object with the Fill tool to shade them.</source>
        <translation>Füllen Sie Bereiche des aktuellen Objekts mit dem Füllwerkzeug, um sie zu schattieren.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ShortcutEditor</name>
    <message>
        <location filename="../ui/src/dialogs/shortcut_editor.cpp" line="31"/>
        <source>Action</source>
        <translation>Aktion</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcut_editor.cpp" line="31"/>
        <source>Shortcut</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcut_editor.cpp" line="31"/>
        <source>Alternative</source>
        <translation>Alternative</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcut_editor.cpp" line="72"/>
        <source>Restore Defaults</source>
        <translation>Standardwerte wiederherstellen</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcut_editor.cpp" line="132"/>
        <source>%1 is used by: %2</source>
        <translation>%1 wird verwendet von: %2</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcut_editor.cpp" line="143"/>
        <source>Conflicting shortcuts:</source>
        <translation>Kollidierende Tastenkürzel:</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ShortcutsDialog</name>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="20"/>
        <source>Keyboard Shortcuts</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="26"/>
        <source>Pan the view</source>
        <translation>Ansicht verschieben</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="26"/>
        <source>Space + drag, or middle button drag</source>
        <translation>Leertaste + Ziehen oder Ziehen mit mittlerer Maustaste</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="27"/>
        <source>Zoom about the cursor</source>
        <translation>Um den Mauszeiger zoomen</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="27"/>
        <source>Mouse wheel</source>
        <translation>Mausrad</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="31"/>
        <source>Action</source>
        <translation>Aktion</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="31"/>
        <source>Shortcut</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="53"/>
        <source>Filter</source>
        <translation>Filter</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SkeletonPanel</name>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="25"/>
        <source>Bone complexity</source>
        <translation>Knochenanzahl</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="25"/>
        <source>Merge junctions</source>
        <translation>Verzweigungen zusammenführen</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="25"/>
        <source>Prune branches</source>
        <translation>Äste beschneiden</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="26"/>
        <source>Collapse short bones</source>
        <translation>Kurze Knochen zusammenfassen</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="27"/>
        <source>Bones</source>
        <translation>Knochen</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="27"/>
        <source>Merge</source>
        <translation>Vereinen</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="27"/>
        <source>Prune</source>
        <translation>Stutzen</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="27"/>
        <source>Collapse</source>
        <translation>Zusammenfassen</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="29"/>
        <source>More bones follow the shape more closely</source>
        <translation>Mehr Knochen folgen der Form genauer</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="30"/>
        <source>Junctions closer than this become one</source>
        <translation>Verzweigungen, die näher beieinander liegen, werden zu einer</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="31"/>
        <source>Remove side branches shorter than this</source>
        <translation>Seitenäste entfernen, die kürzer sind</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="32"/>
        <source>Collapse inner bones shorter than this into one joint</source>
        <translation>Innere Knochen, die kürzer sind, zu einem Gelenk zusammenfassen</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="41"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="55"/>
        <source>Pick the Bone tool (K) and click an object to give it a skeleton.</source>
        <translation>Wählen Sie das Werkzeug Knochen (K) und klicken Sie auf ein Objekt, um ihm ein Skelett zu geben.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SoundController</name>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="42"/>
        <source>Import Soun&amp;d...</source>
        <translation>&amp;Ton importieren...</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="44"/>
        <source>Add a sound file to the soundtrack, starting at the current frame</source>
        <translation>Eine Tondatei zur Tonspur hinzufügen, beginnend beim aktuellen Bild</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="47"/>
        <source>Import Sound</source>
        <translation>Ton importieren</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="48"/>
        <source>Sound files (*.wav *.flac *.mp3 *.ogg *.oga *.opus *.m4a *.aac);;All files (*)</source>
        <translation>Tondateien (*.wav *.flac *.mp3 *.ogg *.oga *.opus *.m4a *.aac);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="74"/>
        <source>The sound &quot;%1&quot; cannot be played: %2</source>
        <translation>Der Ton „%1“ kann nicht abgespielt werden: %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/sound/sound_controller.cpp" line="77"/>
        <source>%n sound(s) cannot be played; &quot;%1&quot;: %2</source>
        <translation>
            <numerusform>%n Sound kann nicht abgespielt werden; „%1“: %2</numerusform>
            <numerusform>%n Sounds können nicht abgespielt werden; „%1“: %2</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="100"/>
        <location filename="../ui/src/sound/sound_controller.cpp" line="140"/>
        <source>Cannot Import Sound</source>
        <translation>Ton kann nicht importiert werden</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="100"/>
        <source>Cannot import &quot;%1&quot;: %2</source>
        <translation>„%1“ kann nicht importiert werden: %2</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="103"/>
        <source>it is not a file.</source>
        <translation>es ist keine Datei.</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="107"/>
        <source>it is larger than %1 MB.</source>
        <translation>sie ist größer als %1 MB.</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="116"/>
        <source>Reading &quot;%1&quot;…</source>
        <translation>„%1“ wird gelesen…</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="141"/>
        <source>Cannot import &quot;%1&quot;: %2 Nothing was changed.</source>
        <translation>„%1“ kann nicht importiert werden: %2 Es wurde nichts geändert.</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="154"/>
        <location filename="../ui/src/sound/sound_controller.cpp" line="156"/>
        <source>Imported &quot;%1&quot; (%2 s).</source>
        <translation>„%1“ importiert (%2 s).</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="183"/>
        <source>Sound Volume</source>
        <translation>Lautstärke</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="183"/>
        <source>Volume of &quot;%1&quot; (%):</source>
        <translation>Lautstärke von „%1“ (%):</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SoundPlayer</name>
    <message>
        <location filename="../ui/src/sound/sound_player.cpp" line="69"/>
        <source>No audio output was found: playing without sound.</source>
        <translation>Keine Audioausgabe gefunden: Wiedergabe ohne Ton.</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_player.cpp" line="80"/>
        <source>The audio output failed: playing without sound.</source>
        <translation>Die Audioausgabe ist fehlgeschlagen: Wiedergabe ohne Ton.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SoundRow</name>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="37"/>
        <source>The soundtrack: drag a sound to move it, right click for its volume</source>
        <translation>Die Tonspur: einen Ton ziehen, um ihn zu verschieben, Rechtsklick für seine Lautstärke</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="133"/>
        <source>+%1 s after the last frame (not played)</source>
        <translation>+%1 s nach dem letzten Bild (nicht abgespielt)</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="163"/>
        <source>No sound: File → Import Sound…</source>
        <translation>Kein Ton: Datei → Ton importieren…</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="219"/>
        <source>%1 (cannot be played)</source>
        <translation>%1 (nicht abspielbar)</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="221"/>
        <source>%1 (reading…)</source>
        <translation>%1 (wird gelesen…)</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="223"/>
        <source>%1 (muted)</source>
        <translation>%1 (stumm)</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="299"/>
        <source>&amp;Mute</source>
        <translation>&amp;Stumm</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="304"/>
        <source>&amp;Volume...</source>
        <translation>&amp;Lautstärke...</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="306"/>
        <source>Delete &amp;Sound</source>
        <translation>Ton &amp;löschen</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SwapActions</name>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="24"/>
        <source>Make S&amp;wappable</source>
        <translation>Aus&amp;tauschbar machen</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="26"/>
        <source>New Mout&amp;h Chart</source>
        <translation>Neue &amp;Mundtabelle</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="29"/>
        <source>&amp;Previous Drawing</source>
        <translation>Vo&amp;rherige Zeichnung</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="32"/>
        <source>Ne&amp;xt Drawing</source>
        <translation>Nächste Zeichn&amp;ung</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="22"/>
        <source>Show Dr&amp;awing</source>
        <translation>Zeichnung anz&amp;eigen</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="35"/>
        <source>New Drawing in S&amp;et</source>
        <translation>Neue Zeichnung &amp;im Satz</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="38"/>
        <source>D&amp;uplicate Drawing in Set</source>
        <translation>Zeichnung im Satz &amp;duplizieren</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="40"/>
        <source>&amp;Rename Drawing...</source>
        <translation>Zeichnung um&amp;benennen…</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="42"/>
        <source>Remove Drawing from Se&amp;t</source>
        <translation>Zei&amp;chnung aus Satz entfernen</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="44"/>
        <source>Make Drawing &amp;Independent</source>
        <translation>Zeichnung l&amp;oslösen</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="47"/>
        <source>Make the object&apos;s drawing the first of a set it swaps between, frame by frame (mouths, hands, blinks)</source>
        <translation>Die Zeichnung des Objekts zur ersten eines Satzes machen, zwischen dem es Bild für Bild wechselt (Münder, Hände, Blinzeln)</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="50"/>
        <source>A new object showing the nine mouth shapes lip sync uses</source>
        <translation>Ein neues Objekt mit den neun Mundformen der Lippensynchronisation</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="52"/>
        <source>This frame keeps its drawing as its own: edits of it no longer reach the other frames</source>
        <translation>Dieses Bild behält seine Zeichnung für sich: Änderungen daran erreichen die anderen Bilder nicht mehr</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="125"/>
        <source>(not swappable)</source>
        <translation>(nicht austauschbar)</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="129"/>
        <source>(unnamed)</source>
        <translation>(ohne Namen)</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="162"/>
        <source>&quot;%1&quot; is swappable: add drawings with Object &gt; New Drawing in Set, and pick one per frame with [ and ]</source>
        <translation>„%1“ ist austauschbar: Zeichnungen mit Objekt &gt; Neue Zeichnung im Satz hinzufügen und pro Bild mit [ und ] wählen</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="190"/>
        <source>New Mouth Chart</source>
        <translation>Neue Mundtabelle</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="191"/>
        <location filename="../ui/src/swap/swap_actions.cpp" line="195"/>
        <source>Mouth</source>
        <translation>Mund</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="201"/>
        <source>A mouth chart on its own layer: nine mouth shapes to redraw in your style; [ and ] swap them, Deform &gt; Lip Sync keys them from the soundtrack</source>
        <translation>Eine Mundtabelle auf eigener Ebene: neun Mundformen zum Neuzeichnen in Ihrem Stil; [ und ] wechseln sie, Verformen &gt; Lippensynchronisation setzt sie nach der Tonspur</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="226"/>
        <source>Rename Drawing</source>
        <translation>Zeichnung umbenennen</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="226"/>
        <source>Name of the drawing:</source>
        <translation>Name der Zeichnung:</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="273"/>
        <source>Drawing &quot;%1&quot;</source>
        <translation>Zeichnung „%1“</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SwapPicker</name>
    <message>
        <location filename="../ui/src/swap/swap_picker.cpp" line="15"/>
        <source>Drawing:</source>
        <translation>Zeichnung:</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_picker.cpp" line="20"/>
        <source>The drawing this object shows in this frame ([ and ] step through them)</source>
        <translation>Die Zeichnung, die dieses Objekt in diesem Bild zeigt ([ und ] blättern durch sie)</translation>
    </message>
</context>
<context>
    <name>finbook::ui::TimelineView</name>
    <message>
        <location filename="../ui/src/timeline/timeline_view.cpp" line="266"/>
        <source>Drag along the frame numbers to scrub through the animation</source>
        <translation>Entlang der Bildnummern ziehen, um durch die Animation zu fahren</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_view.cpp" line="268"/>
        <source>Click to show this frame; drag the picture to move the frame elsewhere; Ctrl- or Shift-click to pick several</source>
        <translation>Klicken zeigt dieses Bild; das Bild ziehen verschiebt es an eine andere Stelle; Ctrl- oder Umschalt-Klick wählt mehrere</translation>
    </message>
</context>
<context>
    <name>finbook::ui::TimelineWidget</name>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="91"/>
        <source>Onion Skin</source>
        <translation>Zwiebelhaut</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="92"/>
        <source>Show neighbouring frames faintly while drawing</source>
        <translation>Benachbarte Einzelbilder beim Zeichnen blass anzeigen</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="108"/>
        <source>Before:</source>
        <translation>Davor:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="109"/>
        <source>How many earlier frames the onion skin shows</source>
        <translation>Wie viele vorherige Einzelbilder die Zwiebelhaut zeigt</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="110"/>
        <source>After:</source>
        <translation>Danach:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="111"/>
        <source>How many later frames the onion skin shows</source>
        <translation>Wie viele folgende Einzelbilder die Zwiebelhaut zeigt</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="142"/>
        <source>Frame %1 of %2 · %3 fps</source>
        <translation>Einzelbild %1 von %2 · %3 fps</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ToolOptionsBar</name>
    <message>
        <location filename="../ui/src/window/tool_options_bar.cpp" line="11"/>
        <source>Tool Options</source>
        <translation>Werkzeugoptionen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/tool_options_bar.cpp" line="56"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>finbook::ui::WelcomeDialog</name>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="37"/>
        <source>Show this page whenever Finbook starts</source>
        <translation>Diese Seite bei jedem Start von Finbook zeigen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="40"/>
        <source>Welcome to Finbook</source>
        <translation>Willkommen bei Finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="50"/>
        <source>&amp;New Animation</source>
        <translation>&amp;Neue Animation</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="50"/>
        <source>Start an empty animation</source>
        <translation>Eine leere Animation beginnen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="51"/>
        <source>&amp;Open...</source>
        <translation>Ö&amp;ffnen...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="51"/>
        <source>Open a .finbook file</source>
        <translation>Eine .finbook-Datei öffnen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="52"/>
        <source>Open the &amp;Example</source>
        <translation>Das &amp;Beispiel öffnen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="53"/>
        <source>A short walk cycle drawn with Finbook, to look at and change</source>
        <translation>Ein kurzer Laufzyklus, mit Finbook gezeichnet, zum Anschauen und Ändern</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="54"/>
        <source>Read the &amp;Manual</source>
        <translation>Das &amp;Handbuch lesen</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="55"/>
        <source>The Finbook Manual (F1 opens it at the tool in hand)</source>
        <translation>Das Finbook-Handbuch (F1 öffnet es beim Werkzeug in der Hand)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="63"/>
        <source>(no recent files yet)</source>
        <translation>(noch keine zuletzt geöffneten Dateien)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="70"/>
        <source>&lt;h2&gt;Draw — bend — play&lt;/h2&gt;&lt;p&gt;&lt;b&gt;1. Draw.&lt;/b&gt; Take the pen (&lt;b&gt;B&lt;/b&gt;) and draw a character; a tablet&apos;s pressure shapes the line. Close its outline loosely: small gaps close by themselves. Pick a colour in the Palette and click inside with the fill (&lt;b&gt;F&lt;/b&gt;).&lt;/p&gt;&lt;p&gt;&lt;b&gt;2. Bend.&lt;/b&gt; Instead of drawing the next frame again, duplicate the frame (&lt;b&gt;Ctrl+D&lt;/b&gt;) and bend the copy: click the drawing with the bone tool (&lt;b&gt;K&lt;/b&gt;) and drag a bone, or put pins on it (&lt;b&gt;P&lt;/b&gt;) and drag one; the rest follows as if drawn on rubber. The bent drawing is lines again: keep drawing on it.&lt;/p&gt;&lt;p&gt;&lt;b&gt;3. Play.&lt;/b&gt; Press &lt;b&gt;Return&lt;/b&gt; to play; Frame → In-betweens fills the frames between two poses. Onion skin (&lt;b&gt;O&lt;/b&gt;) shows the neighbours faintly. Save with &lt;b&gt;Ctrl+S&lt;/b&gt;, export a GIF, a video or a Lottie animation with File → Export.&lt;/p&gt;&lt;p&gt;&lt;a href=&quot;getting-started.md&quot;&gt;Read “Getting Started” in the manual&lt;/a&gt;, or press &lt;b&gt;F1&lt;/b&gt; at any time for the page of the tool in hand.&lt;/p&gt;</source>
        <translation>&lt;h2&gt;Zeichnen — biegen — abspielen&lt;/h2&gt;&lt;p&gt;&lt;b&gt;1. Zeichnen.&lt;/b&gt; Nimm den Stift (&lt;b&gt;B&lt;/b&gt;) und zeichne eine Figur; der Druck eines Grafiktabletts formt die Linie. Schließe den Umriss ruhig locker: kleine Lücken schließen sich von selbst. Wähle eine Farbe in der Palette und klicke mit der Füllung (&lt;b&gt;F&lt;/b&gt;) hinein.&lt;/p&gt;&lt;p&gt;&lt;b&gt;2. Biegen.&lt;/b&gt; Statt das nächste Bild neu zu zeichnen, dupliziere das Bild (&lt;b&gt;Ctrl+D&lt;/b&gt;) und biege die Kopie: klicke die Zeichnung mit dem Knochenwerkzeug (&lt;b&gt;K&lt;/b&gt;) an und ziehe einen Knochen, oder setze Pins (&lt;b&gt;P&lt;/b&gt;) und ziehe einen; der Rest folgt wie auf Gummi gezeichnet. Die gebogene Zeichnung besteht wieder aus Linien: zeichne einfach weiter.&lt;/p&gt;&lt;p&gt;&lt;b&gt;3. Abspielen.&lt;/b&gt; &lt;b&gt;Return&lt;/b&gt; spielt ab; Bild → Zwischenbilder füllt die Bilder zwischen zwei Posen. Die Zwiebelhaut (&lt;b&gt;O&lt;/b&gt;) zeigt die Nachbarn blass. Speichere mit &lt;b&gt;Ctrl+S&lt;/b&gt;, exportiere ein GIF, ein Video oder eine Lottie-Animation mit Datei → Exportieren.&lt;/p&gt;&lt;p&gt;&lt;a href=&quot;getting-started.md&quot;&gt;„Getting Started“ im Handbuch lesen&lt;/a&gt;, oder jederzeit &lt;b&gt;F1&lt;/b&gt; für die Seite zum Werkzeug in der Hand.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="91"/>
        <source>Recent files:</source>
        <translation>Zuletzt geöffnet:</translation>
    </message>
</context>
</TS>
