<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>Command</name>
    <message>
        <location filename="../model/src/commands.cpp" line="27"/>
        <source>Draw Stroke</source>
        <translation>Strich zeichnen</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="51"/>
        <source>Erase Stroke</source>
        <translation>Strich radieren</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="80"/>
        <source>Move Strokes to Object</source>
        <translation>Striche in Objekt verschieben</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="177"/>
        <source>New Object</source>
        <translation>Neues Objekt</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="205"/>
        <source>Delete Object</source>
        <translation>Objekt löschen</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="234"/>
        <source>Rename Object</source>
        <translation>Objekt umbenennen</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="259"/>
        <source>Reorder Object</source>
        <translation>Objekt umsortieren</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="290"/>
        <source>Show Object</source>
        <translation>Objekt einblenden</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="290"/>
        <source>Hide Object</source>
        <translation>Objekt ausblenden</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="292"/>
        <source>Lock Object</source>
        <translation>Objekt sperren</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="292"/>
        <source>Unlock Object</source>
        <translation>Objekt entsperren</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="325"/>
        <source>Insert Frame</source>
        <translation>Einzelbild einfügen</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="329"/>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="348"/>
        <source>Duplicate Frame</source>
        <translation>Einzelbild duplizieren</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="393"/>
        <source>Delete Frame</source>
        <translation>Einzelbild löschen</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="419"/>
        <source>Move Frame</source>
        <translation>Einzelbild verschieben</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="442"/>
        <source>Change Frame Exposure</source>
        <translation>Haltedauer des Einzelbilds ändern</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="480"/>
        <source>Change Document Settings</source>
        <translation>Dokumenteinstellungen ändern</translation>
    </message>
    <message>
        <location filename="../model/src/object_commands.cpp" line="38"/>
        <source>Merge Objects</source>
        <translation>Objekte zusammenführen</translation>
    </message>
    <message>
        <location filename="../model/src/pin_commands.cpp" line="29"/>
        <source>Add Pin</source>
        <translation>Pin setzen</translation>
    </message>
    <message>
        <location filename="../model/src/pin_commands.cpp" line="57"/>
        <source>Remove Pin</source>
        <translation>Pin entfernen</translation>
    </message>
    <message>
        <location filename="../model/src/pin_commands.cpp" line="88"/>
        <source>Move Pin</source>
        <translation>Pin verschieben</translation>
    </message>
    <message>
        <location filename="../model/src/pin_commands.cpp" line="133"/>
        <source>Reset Deformation</source>
        <translation>Verformung zurücksetzen</translation>
    </message>
    <message>
        <location filename="../model/src/pin_commands.cpp" line="162"/>
        <source>Apply Deformation</source>
        <translation>Verformung anwenden</translation>
    </message>
    <message>
        <location filename="../model/src/pin_commands.cpp" line="204"/>
        <source>Change Mesh Density</source>
        <translation>Netzdichte ändern</translation>
    </message>
</context>
<context>
    <name>CommandLine</name>
    <message>
        <location filename="../app/cli.cpp" line="67"/>
        <source>Cannot create the output folder %1.</source>
        <translation>Der Ausgabeordner %1 kann nicht angelegt werden.</translation>
    </message>
    <message>
        <location filename="../app/cli.cpp" line="76"/>
        <source>Cannot write %1 (is the disk full or read-only?).</source>
        <translation>%1 kann nicht geschrieben werden (ist der Datenträger voll oder schreibgeschützt?).</translation>
    </message>
    <message>
        <location filename="../app/cli.cpp" line="114"/>
        <source>No command given; see finbook --help.</source>
        <translation>Kein Befehl angegeben; siehe finbook --help.</translation>
    </message>
    <message>
        <location filename="../app/cli.cpp" line="118"/>
        <source>Usage: finbook info FILE</source>
        <translation>Aufruf: finbook info FILE</translation>
    </message>
    <message>
        <location filename="../app/cli.cpp" line="128"/>
        <source>Usage: finbook export FILE OUTDIR</source>
        <translation>Aufruf: finbook export FILE OUTDIR</translation>
    </message>
    <message>
        <location filename="../app/cli.cpp" line="131"/>
        <source>Unknown command &quot;%1&quot;; see finbook --help.</source>
        <translation>Unbekannter Befehl „%1“; siehe finbook --help.</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="25"/>
        <source>Finbook, a flipbook animation editor.

  finbook [FILE]               open FILE in the editor
  finbook info FILE            print a JSON summary of FILE
  finbook export FILE OUTDIR   render every frame to OUTDIR/frame_0001.png ...</source>
        <translation>Finbook, ein Daumenkino-Animationseditor.

  finbook [FILE]               FILE im Editor öffnen
  finbook info FILE            eine JSON-Zusammenfassung von FILE ausgeben
  finbook export FILE OUTDIR   alle Einzelbilder rendern nach OUTDIR/frame_0001.png ...</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="35"/>
        <source>Use LANGUAGE (e.g. de, en) instead of the system&apos;s.</source>
        <translation>LANGUAGE (z. B. de, en) statt der Systemsprache verwenden.</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="40"/>
        <source>FILE, or a command.</source>
        <translation>FILE oder ein Befehl.</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="44"/>
        <source>see finbook --help</source>
        <comment>after an error</comment>
        <translation>siehe finbook --help</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="67"/>
        <source>Unknown command &quot;%1&quot;; %2.</source>
        <translation>Unbekannter Befehl „%1“; %2.</translation>
    </message>
</context>
<context>
    <name>Deformation</name>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="73"/>
        <source>The object has no strokes to deform.</source>
        <translation>Das Objekt hat keine Striche, die sich verformen ließen.</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="78"/>
        <source>This drawing cannot be meshed for deformation: %1</source>
        <translation>Für diese Zeichnung lässt sich kein Verformungsnetz erstellen: %1</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="102"/>
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="111"/>
        <source>The pins cannot be solved on this drawing: %1</source>
        <translation>Die Pins lassen sich auf dieser Zeichnung nicht berechnen: %1</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="137"/>
        <source>The pins could not be solved: %1</source>
        <translation>Die Pins konnten nicht berechnet werden: %1</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="144"/>
        <source>The deformation produced invalid points; it was not applied.</source>
        <translation>Die Verformung hat ungültige Punkte ergeben; sie wurde nicht angewendet.</translation>
    </message>
</context>
<context>
    <name>FinbookFile</name>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="34"/>
        <source>frame %1</source>
        <translation>Einzelbild %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="36"/>
        <source>, object &quot;%1&quot;</source>
        <translation>, Objekt „%1“</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="37"/>
        <source>, object %1</source>
        <translation>, Objekt %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="39"/>
        <source>, stroke %1</source>
        <translation>, Strich %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="43"/>
        <source>stroke data %1</source>
        <translation>Strichdaten %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="45"/>
        <source>pose %1</source>
        <translation>Pose %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="72"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="80"/>
        <source>the file ends inside %1 (%2 bytes needed, %3 left)</source>
        <translation>%1 ist unvollständig, die Datei endet vorzeitig (%2 Bytes benötigt, %3 übrig)</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="96"/>
        <source>%1 claims %2 entries but only %3 bytes remain</source>
        <translation>%1 gibt %2 Einträge an, es sind aber nur noch %3 Bytes übrig</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="122"/>
        <source>%1 has %2 unexpected bytes at its end</source>
        <translation>%1 hat am Ende %2 unerwartete Bytes</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="29"/>
        <source>%1 The file is incomplete (perhaps an interrupted copy or save); if there is a backup with the same name ending in ~, open that instead.</source>
        <translation>%1 Die Datei ist unvollständig (vielleicht wurde ein Kopier- oder Speichervorgang unterbrochen); falls es eine Sicherungskopie mit demselben Namen und angehängtem ~ gibt, öffnen Sie stattdessen diese.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="35"/>
        <source>%1 The file is damaged; if there is a backup with the same name ending in ~, open that instead.</source>
        <translation>%1 Die Datei ist beschädigt; falls es eine Sicherungskopie mit demselben Namen und angehängtem ~ gibt, öffnen Sie stattdessen diese.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="57"/>
        <source>Could not save &quot;%1&quot;: %2. The previous file is unchanged; free some disk space or choose another folder, then save again.</source>
        <translation>„%1“ konnte nicht gespeichert werden: %2. Die bisherige Datei ist unverändert; geben Sie Speicherplatz frei oder wählen Sie einen anderen Ordner und speichern Sie dann erneut.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="71"/>
        <source>the old backup &quot;%1&quot; cannot be replaced</source>
        <translation>die alte Sicherungskopie „%1“ kann nicht ersetzt werden</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="81"/>
        <source>the backup &quot;%1&quot; cannot be written (%2)</source>
        <translation>die Sicherungskopie „%1“ kann nicht geschrieben werden (%2)</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="106"/>
        <source>Cannot open &quot;%1&quot;: %2. Check that the file exists and that you may read it.</source>
        <translation>„%1“ kann nicht geöffnet werden: %2. Prüfen Sie, ob die Datei existiert und ob Sie sie lesen dürfen.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="108"/>
        <source>it is a folder</source>
        <translation>es ist ein Ordner</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="116"/>
        <source>Cannot open &quot;%1&quot;: it is too large for the memory available.</source>
        <translation>„%1“ kann nicht geöffnet werden: die Datei ist zu groß für den verfügbaren Arbeitsspeicher.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="122"/>
        <source>Cannot read &quot;%1&quot;: %2.</source>
        <translation>„%1“ kann nicht gelesen werden: %2.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="126"/>
        <source>Cannot open &quot;%1&quot;. %2</source>
        <translation>„%1“ kann nicht geöffnet werden. %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="146"/>
        <source>the drawing holds invalid data (%1)</source>
        <translation>die Zeichnung enthält ungültige Daten (%1)</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="33"/>
        <source>unknown %1 %2</source>
        <translation>unbekannter %1 %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="36"/>
        <source>it holds data (&quot;%1&quot;) that this version of Finbook does not know, so it was probably made by a newer Finbook; please update Finbook to open it</source>
        <translation>die Datei enthält Daten („%1“), die diese Finbook-Version nicht kennt, und wurde daher wohl mit einer neueren Finbook-Version erstellt; bitte aktualisieren Sie Finbook, um sie zu öffnen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="57"/>
        <source>the file is empty</source>
        <translation>die Datei ist leer</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="59"/>
        <source>the file header</source>
        <translation>der Dateikopf</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="61"/>
        <source>it is not a Finbook animation</source>
        <translation>die Datei ist keine Finbook-Animation</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="63"/>
        <source>the file ends inside its header</source>
        <translation>die Datei endet mitten im Dateikopf</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="64"/>
        <source>the format version</source>
        <translation>die Formatversion</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="67"/>
        <source>it was made by a newer version of Finbook (file format %1; this version reads up to %2); please update Finbook to open it</source>
        <translation>die Datei wurde mit einer neueren Finbook-Version erstellt (Dateiformat %1; diese Version liest bis %2); bitte aktualisieren Sie Finbook, um sie zu öffnen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="74"/>
        <source>the format version %1 does not exist</source>
        <translation>die Formatversion %1 gibt es nicht</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="84"/>
        <source>the file&apos;s section list</source>
        <translation>die Abschnittsliste der Datei</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="85"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="86"/>
        <source>a section header</source>
        <translation>ein Abschnittskopf</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="87"/>
        <source>section %1</source>
        <translation>Abschnitt %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="91"/>
        <source>the file ends inside this section (%1 bytes announced, %2 left)</source>
        <translation>die Datei endet mitten in diesem Abschnitt (%1 Bytes angekündigt, %2 übrig)</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="94"/>
        <source>a section</source>
        <translation>ein Abschnitt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="98"/>
        <source>section %1 is missing</source>
        <translation>Abschnitt %1 fehlt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="99"/>
        <source>the end marker</source>
        <translation>die Endmarke</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="100"/>
        <source>the file</source>
        <translation>die Datei</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="105"/>
        <source>section</source>
        <translation>Abschnitt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="110"/>
        <source>the section is repeated or out of order</source>
        <translation>der Abschnitt ist doppelt vorhanden oder steht an der falschen Stelle</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="125"/>
        <source>the section</source>
        <translation>der Abschnitt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="131"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="349"/>
        <source>the document settings</source>
        <translation>die Dokumenteinstellungen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="133"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="134"/>
        <source>the canvas size</source>
        <translation>die Leinwandgröße</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="137"/>
        <source>the canvas size %1×%2 is outside 1 to %3 pixels</source>
        <translation>die Leinwandgröße %1×%2 liegt nicht zwischen 1 und %3 Pixeln</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="142"/>
        <source>the background colour</source>
        <translation>die Hintergrundfarbe</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="143"/>
        <source>the frame rate</source>
        <translation>die Bildrate</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="145"/>
        <source>the frame rate %1 is outside %2 to %3</source>
        <translation>die Bildrate %1 liegt nicht zwischen %2 und %3</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="150"/>
        <source>the loop flag</source>
        <translation>die Endlosschleifen-Angabe</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="153"/>
        <source>the loop flag %1 is neither 0 nor 1</source>
        <translation>die Endlosschleifen-Angabe %1 ist weder 0 noch 1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="155"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="156"/>
        <source>the play range</source>
        <translation>der Wiedergabebereich</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="160"/>
        <source>the play range %1 to %2 is invalid</source>
        <translation>der Wiedergabebereich %1 bis %2 ist ungültig</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="161"/>
        <source>the next id</source>
        <translation>die nächste ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="166"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="168"/>
        <source>the frame list</source>
        <translation>die Einzelbildliste</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="173"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="174"/>
        <source>a frame</source>
        <translation>ein Einzelbild</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="183"/>
        <source>a frame id</source>
        <translation>eine Einzelbild-ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="184"/>
        <source>the frame</source>
        <translation>das Einzelbild</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="185"/>
        <source>a frame hold</source>
        <translation>eine Haltedauer</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="188"/>
        <source>the hold %1 is outside 1 to %2</source>
        <translation>die Haltedauer %1 liegt nicht zwischen 1 und %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="191"/>
        <source>the object list</source>
        <translation>die Objektliste</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="195"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="196"/>
        <source>an object</source>
        <translation>ein Objekt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="201"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="202"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="269"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="270"/>
        <source>a chunk header</source>
        <translation>ein Blockkopf</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="203"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="271"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="284"/>
        <source>a chunk</source>
        <translation>ein Block</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="204"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="281"/>
        <source>chunk</source>
        <translation>Block</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="212"/>
        <source>an object id</source>
        <translation>eine Objekt-ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="213"/>
        <source>the object</source>
        <translation>das Objekt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="214"/>
        <source>the object flags</source>
        <translation>die Objektattribute</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="217"/>
        <source>the object flags 0x%1 are unknown</source>
        <translation>die Objektattribute 0x%1 sind unbekannt</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="220"/>
        <source>the mesh density</source>
        <translation>die Netzdichte</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="223"/>
        <source>the mesh density %1 is not a number from 0 to 1000</source>
        <translation>die Netzdichte %1 ist keine Zahl von 0 bis 1000</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="225"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="231"/>
        <source>the object name</source>
        <translation>der Objektname</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="228"/>
        <source>the object name is %1 bytes long (at most %2)</source>
        <translation>der Objektname ist %1 Bytes lang (höchstens %2)</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="237"/>
        <source>the object name is not valid UTF-8 text</source>
        <translation>der Objektname ist kein gültiger UTF-8-Text</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="241"/>
        <source>the stroke list</source>
        <translation>die Strichliste</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="247"/>
        <source>a stroke id</source>
        <translation>eine Strich-ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="248"/>
        <source>the stroke</source>
        <translation>der Strich</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="249"/>
        <source>a stroke reference</source>
        <translation>ein Strichverweis</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="251"/>
        <source>it refers to stroke data %1 of %2</source>
        <translation>er verweist auf Strichdaten %1 von %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="274"/>
        <source>chunk %1 appears twice</source>
        <translation>Block %1 kommt doppelt vor</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="290"/>
        <source>the pin list</source>
        <translation>die Pin-Liste</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="293"/>
        <source>a pin id</source>
        <translation>eine Pin-ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="294"/>
        <source>pin %1</source>
        <translation>Pin %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="297"/>
        <source>a pin position</source>
        <translation>eine Pin-Position</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="300"/>
        <source>pin %1 has a non-finite position</source>
        <translation>Pin %1 hat eine nicht endliche Position</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="309"/>
        <source>a pose reference</source>
        <translation>ein Posenverweis</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="311"/>
        <source>its pose refers to pose %1 of %2</source>
        <translation>seine Pose verweist auf Pose %1 von %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="315"/>
        <source>its pose: %1</source>
        <translation>seine Pose: %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="319"/>
        <source>its pose has %1 strokes but the object has %2</source>
        <translation>seine Pose hat %1 Striche, das Objekt aber %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="326"/>
        <source>stroke %1 has %2 points but its pose has %3</source>
        <translation>Strich %1 hat %2 Punkte, seine Pose aber %3</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="338"/>
        <source>%1 has no id</source>
        <translation>%1 hat keine ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="341"/>
        <source>%1 has the id %2, which is already used</source>
        <translation>%1 hat die ID %2, die bereits vergeben ist</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="360"/>
        <source>the next free id %1 is not above the largest id %2</source>
        <translation>die nächste freie ID %1 ist nicht größer als die größte ID %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="374"/>
        <source>there is not enough memory to open this file</source>
        <translation>es ist nicht genug Arbeitsspeicher vorhanden, um diese Datei zu öffnen</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="22"/>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="24"/>
        <source>a stroke</source>
        <translation>ein Strich</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="26"/>
        <source>point %1 has a non-finite coordinate</source>
        <translation>Punkt %1 hat eine nicht endliche Koordinate</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="42"/>
        <source>the stroke table</source>
        <translation>die Strichtabelle</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="47"/>
        <source>a stroke colour</source>
        <translation>eine Strichfarbe</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="48"/>
        <source>a stroke width</source>
        <translation>eine Strichbreite</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="51"/>
        <source>the width %1 is not a positive number</source>
        <translation>die Breite %1 ist keine positive Zahl</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="60"/>
        <source>the pose table</source>
        <translation>die Posentabelle</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="66"/>
        <source>a pose</source>
        <translation>eine Pose</translation>
    </message>
</context>
<context>
    <name>ObjectListModel</name>
    <message numerus="yes">
        <location filename="../model/src/object_list_model.cpp" line="160"/>
        <source>%1: %n stroke(s)</source>
        <translation>
            <numerusform>%1: %n Strich</numerusform>
            <numerusform>%1: %n Striche</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>StrokeEditing</name>
    <message>
        <location filename="../ui/src/stroke_editing.cpp" line="84"/>
        <source>There is no frame to draw on. Insert a frame first.</source>
        <translation>Es gibt kein Einzelbild, auf dem gezeichnet werden kann. Fügen Sie zuerst ein Einzelbild ein.</translation>
    </message>
    <message>
        <location filename="../ui/src/stroke_editing.cpp" line="87"/>
        <source>The object &quot;%1&quot; is locked. Unlock it in the Objects panel to draw on it.</source>
        <translation>Das Objekt „%1“ ist gesperrt. Entsperren Sie es im Bedienfeld Objekte, um darauf zu zeichnen.</translation>
    </message>
    <message>
        <location filename="../ui/src/stroke_editing.cpp" line="90"/>
        <source>The object &quot;%1&quot; is hidden. Show it in the Objects panel to draw on it.</source>
        <translation>Das Objekt „%1“ ist ausgeblendet. Blenden Sie es im Bedienfeld Objekte ein, um darauf zu zeichnen.</translation>
    </message>
    <message>
        <location filename="../ui/src/stroke_editing.cpp" line="109"/>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <location filename="../ui/src/stroke_editing.cpp" line="140"/>
        <source>Delete Strokes</source>
        <translation>Striche löschen</translation>
    </message>
    <message>
        <location filename="../ui/src/stroke_editing.cpp" line="188"/>
        <source>Cut</source>
        <translation>Ausschneiden</translation>
    </message>
    <message>
        <location filename="../ui/src/stroke_editing.cpp" line="208"/>
        <source>The clipboard holds strokes this version of Finbook cannot read.</source>
        <translation>Die Zwischenablage enthält Striche, die diese Finbook-Version nicht lesen kann.</translation>
    </message>
    <message>
        <location filename="../ui/src/stroke_editing.cpp" line="211"/>
        <source>Paste</source>
        <translation>Einfügen</translation>
    </message>
</context>
<context>
    <name>finbook::model::FrameListModel</name>
    <message>
        <location filename="../model/src/frame_list_model.cpp" line="132"/>
        <source>Frame %1, held for %2 frames</source>
        <translation>Einzelbild %1, %2 Einzelbilder lang gehalten</translation>
    </message>
    <message>
        <location filename="../model/src/frame_list_model.cpp" line="133"/>
        <source>Frame %1</source>
        <translation>Einzelbild %1</translation>
    </message>
</context>
<context>
    <name>finbook::ui::BrushToolBar</name>
    <message>
        <location filename="../ui/src/brush_tool_bar.cpp" line="13"/>
        <source>Brush</source>
        <translation>Pinsel</translation>
    </message>
    <message>
        <location filename="../ui/src/brush_tool_bar.cpp" line="28"/>
        <source>Width:</source>
        <translation>Breite:</translation>
    </message>
    <message>
        <location filename="../ui/src/brush_tool_bar.cpp" line="33"/>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <location filename="../ui/src/brush_tool_bar.cpp" line="35"/>
        <source>Smoothing:</source>
        <translation>Glättung:</translation>
    </message>
    <message>
        <location filename="../ui/src/brush_tool_bar.cpp" line="38"/>
        <source>How much a stroke is smoothed when the pen lifts</source>
        <translation>Wie stark ein Strich beim Absetzen des Stifts geglättet wird</translation>
    </message>
    <message>
        <location filename="../ui/src/brush_tool_bar.cpp" line="66"/>
        <source>Pen colour %1</source>
        <translation>Stiftfarbe %1</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ColorButton</name>
    <message>
        <location filename="../ui/src/color_button.cpp" line="13"/>
        <source>Choose a colour</source>
        <translation>Eine Farbe wählen</translation>
    </message>
    <message>
        <location filename="../ui/src/color_button.cpp" line="31"/>
        <source>Choose Colour</source>
        <translation>Farbe wählen</translation>
    </message>
</context>
<context>
    <name>finbook::ui::DeformActions</name>
    <message>
        <location filename="../ui/src/deform_actions.cpp" line="17"/>
        <source>&amp;Reset Pose</source>
        <translation>Pose &amp;zurücksetzen</translation>
    </message>
    <message>
        <location filename="../ui/src/deform_actions.cpp" line="19"/>
        <source>Move every pin of the current object back to where it was put</source>
        <translation>Alle Pins des aktuellen Objekts an die Stelle zurücksetzen, an der sie gesetzt wurden</translation>
    </message>
    <message>
        <location filename="../ui/src/deform_actions.cpp" line="20"/>
        <source>&amp;Apply Pose to Drawing</source>
        <translation>Pose auf Zeichnung &amp;anwenden</translation>
    </message>
    <message>
        <location filename="../ui/src/deform_actions.cpp" line="22"/>
        <source>Make the bent drawing the object&apos;s new strokes and remove its pins</source>
        <translation>Die verformte Zeichnung zu den neuen Strichen des Objekts machen und seine Pins entfernen</translation>
    </message>
    <message>
        <location filename="../ui/src/deform_actions.cpp" line="23"/>
        <source>Remove All &amp;Pins</source>
        <translation>Alle &amp;Pins entfernen</translation>
    </message>
    <message>
        <location filename="../ui/src/deform_actions.cpp" line="37"/>
        <source>Remove All Pins</source>
        <translation>Alle Pins entfernen</translation>
    </message>
    <message>
        <location filename="../ui/src/deform_actions.cpp" line="45"/>
        <source>Preparing the deformation…</source>
        <translation>Verformung wird vorbereitet…</translation>
    </message>
    <message>
        <location filename="../ui/src/deform_actions.cpp" line="55"/>
        <source>R&amp;igidity</source>
        <translation>&amp;Steifigkeit</translation>
    </message>
    <message>
        <location filename="../ui/src/deform_actions.cpp" line="62"/>
        <source>As in the Paper (Two Steps)</source>
        <translation>Wie in der Veröffentlichung (zwei Schritte)</translation>
    </message>
    <message>
        <location filename="../ui/src/deform_actions.cpp" line="63"/>
        <source>Stiffer (+1 Pass)</source>
        <translation>Steifer (+1 Durchgang)</translation>
    </message>
    <message>
        <location filename="../ui/src/deform_actions.cpp" line="64"/>
        <source>Stiffest (+3 Passes)</source>
        <translation>Am steifsten (+3 Durchgänge)</translation>
    </message>
    <message>
        <location filename="../ui/src/deform_actions.cpp" line="95"/>
        <source>Mesh density </source>
        <translation>Netzdichte </translation>
    </message>
    <message>
        <location filename="../ui/src/deform_actions.cpp" line="96"/>
        <source>How fine the current object&apos;s deformation mesh is (1 = default)</source>
        <translation>Wie fein das Verformungsnetz des aktuellen Objekts ist (1 = Standard)</translation>
    </message>
</context>
<context>
    <name>finbook::ui::DocumentSettingsDialog</name>
    <message>
        <location filename="../ui/src/document_settings_dialog.cpp" line="26"/>
        <source>Start again after the last frame</source>
        <translation>Nach dem letzten Einzelbild wieder von vorn beginnen</translation>
    </message>
    <message>
        <location filename="../ui/src/document_settings_dialog.cpp" line="30"/>
        <source>Document Settings</source>
        <translation>Dokumenteinstellungen</translation>
    </message>
    <message>
        <location filename="../ui/src/document_settings_dialog.cpp" line="32"/>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <location filename="../ui/src/document_settings_dialog.cpp" line="35"/>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <location filename="../ui/src/document_settings_dialog.cpp" line="40"/>
        <source>Last</source>
        <translation>Letztes</translation>
    </message>
    <message>
        <location filename="../ui/src/document_settings_dialog.cpp" line="50"/>
        <source>to</source>
        <translation>bis</translation>
    </message>
    <message>
        <location filename="../ui/src/document_settings_dialog.cpp" line="54"/>
        <source>&amp;Frame rate:</source>
        <translation>&amp;Bildrate:</translation>
    </message>
    <message>
        <location filename="../ui/src/document_settings_dialog.cpp" line="55"/>
        <source>Canvas size:</source>
        <translation>Leinwandgröße:</translation>
    </message>
    <message>
        <location filename="../ui/src/document_settings_dialog.cpp" line="56"/>
        <source>&amp;Background:</source>
        <translation>&amp;Hintergrund:</translation>
    </message>
    <message>
        <location filename="../ui/src/document_settings_dialog.cpp" line="57"/>
        <source>Loop:</source>
        <translation>Endlosschleife:</translation>
    </message>
    <message>
        <location filename="../ui/src/document_settings_dialog.cpp" line="58"/>
        <source>Play frames:</source>
        <translation>Einzelbilder abspielen:</translation>
    </message>
    <message>
        <location filename="../ui/src/document_settings_dialog.cpp" line="125"/>
        <source>Background Colour</source>
        <translation>Hintergrundfarbe</translation>
    </message>
</context>
<context>
    <name>finbook::ui::FrameActions</name>
    <message>
        <location filename="../ui/src/frame_actions.cpp" line="13"/>
        <source>Insert Frame &amp;Before</source>
        <translation>Einzelbild &amp;davor einfügen</translation>
    </message>
    <message>
        <location filename="../ui/src/frame_actions.cpp" line="15"/>
        <source>&amp;Insert Frame After</source>
        <translation>Einzelbild da&amp;nach einfügen</translation>
    </message>
    <message>
        <location filename="../ui/src/frame_actions.cpp" line="17"/>
        <source>&amp;Duplicate Frame</source>
        <translation>Einzelbild d&amp;uplizieren</translation>
    </message>
    <message>
        <location filename="../ui/src/frame_actions.cpp" line="19"/>
        <source>De&amp;lete Frame</source>
        <translation>Einzelbild &amp;löschen</translation>
    </message>
    <message>
        <location filename="../ui/src/frame_actions.cpp" line="22"/>
        <source>Move Frame &amp;Left</source>
        <translation>Einzelbild nach l&amp;inks verschieben</translation>
    </message>
    <message>
        <location filename="../ui/src/frame_actions.cpp" line="24"/>
        <source>Move Frame &amp;Right</source>
        <translation>Einzelbild nach &amp;rechts verschieben</translation>
    </message>
    <message>
        <location filename="../ui/src/frame_actions.cpp" line="27"/>
        <source>Hold &amp;Longer</source>
        <translation>Län&amp;ger halten</translation>
    </message>
    <message>
        <location filename="../ui/src/frame_actions.cpp" line="29"/>
        <source>Hold &amp;Shorter</source>
        <translation>&amp;Kürzer halten</translation>
    </message>
    <message>
        <location filename="../ui/src/frame_actions.cpp" line="32"/>
        <source>&amp;Previous Frame</source>
        <translation>&amp;Vorheriges Einzelbild</translation>
    </message>
    <message>
        <location filename="../ui/src/frame_actions.cpp" line="35"/>
        <source>&amp;Next Frame</source>
        <translation>Nä&amp;chstes Einzelbild</translation>
    </message>
</context>
<context>
    <name>finbook::ui::HandTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tool_hand.h" line="16"/>
        <source>Hand</source>
        <translation>Hand</translation>
    </message>
</context>
<context>
    <name>finbook::ui::MainWindow</name>
    <message>
        <location filename="../ui/src/main_window.cpp" line="106"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window.cpp" line="130"/>
        <source>Timeline</source>
        <translation>Zeitleiste</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window.cpp" line="131"/>
        <source>Objects</source>
        <translation>Objekte</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window.cpp" line="134"/>
        <source>&lt;opened document&gt;</source>
        <translation>&lt;geöffnetes Dokument&gt;</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window.cpp" line="135"/>
        <source>Undo History</source>
        <translation>Verlauf</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window.cpp" line="165"/>
        <source>%1, %2 px</source>
        <translation>%1, %2 px</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window.cpp" line="176"/>
        <source>Frame %1 / %2</source>
        <translation>Einzelbild %1 / %2</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window.cpp" line="177"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window.cpp" line="182"/>
        <location filename="../ui/src/main_window_files.cpp" line="200"/>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window.cpp" line="183"/>
        <source>%1[*] - Finbook</source>
        <translation>%1[*] – Finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_files.cpp" line="25"/>
        <source>Finbook animations (*.finbook);;All files (*)</source>
        <translation>Finbook-Animationen (*.finbook);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_files.cpp" line="36"/>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_files.cpp" line="65"/>
        <source>Cannot Open File</source>
        <translation>Datei kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_files.cpp" line="93"/>
        <source>Cannot Save File</source>
        <translation>Datei kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_files.cpp" line="99"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_files.cpp" line="123"/>
        <source>Exporting frames...</source>
        <translation>Einzelbilder werden exportiert...</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_files.cpp" line="123"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_files.cpp" line="132"/>
        <source>Cannot Export Frames</source>
        <translation>Einzelbilder können nicht exportiert werden</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_files.cpp" line="133"/>
        <source>Cannot write %1. Check that the folder is writable and the disk is not full, then export again.</source>
        <translation>%1 kann nicht geschrieben werden. Prüfen Sie, ob der Ordner beschreibbar und der Datenträger nicht voll ist, und exportieren Sie erneut.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/main_window_files.cpp" line="140"/>
        <source>Exported %n frame(s) to %1</source>
        <translation>
            <numerusform>%n Einzelbild nach %1 exportiert</numerusform>
            <numerusform>%n Einzelbilder nach %1 exportiert</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_files.cpp" line="177"/>
        <source>&amp;%1 %2</source>
        <translation>&amp;%1 %2</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_files.cpp" line="186"/>
        <source>No recent files</source>
        <translation>Keine zuletzt geöffneten Dateien</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_files.cpp" line="202"/>
        <source>Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_files.cpp" line="203"/>
        <source>&quot;%1&quot; has changes that are not saved. Save them before going on?</source>
        <translation>„%1“ hat ungespeicherte Änderungen. Vorher speichern?</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_files.cpp" line="209"/>
        <source>Open Animation</source>
        <translation>Animation öffnen</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_files.cpp" line="215"/>
        <source>Save Animation</source>
        <translation>Animation speichern</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_files.cpp" line="216"/>
        <source>untitled.finbook</source>
        <translation>unbenannt.finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_files.cpp" line="222"/>
        <source>Export Frames to Folder</source>
        <translation>Einzelbilder in Ordner exportieren</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="40"/>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="52"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="53"/>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="55"/>
        <source>&amp;Open...</source>
        <translation>Ö&amp;ffnen...</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="59"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="63"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="65"/>
        <source>Save &amp;As...</source>
        <translation>Speichern &amp;unter...</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="67"/>
        <source>&amp;Export Frames...</source>
        <translation>Einzelbilder &amp;exportieren...</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="69"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="83"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="85"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="88"/>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="97"/>
        <source>Paste</source>
        <translation>Einfügen</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="99"/>
        <source>Cu&amp;t</source>
        <translation>&amp;Ausschneiden</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="101"/>
        <source>&amp;Copy</source>
        <translation>&amp;Kopieren</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="103"/>
        <source>&amp;Paste</source>
        <translation>&amp;Einfügen</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="109"/>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="112"/>
        <source>Select &amp;All</source>
        <translation>Alles a&amp;uswählen</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="118"/>
        <source>Dese&amp;lect</source>
        <translation>Auswahl au&amp;fheben</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="125"/>
        <source>D&amp;ocument Settings...</source>
        <translation>D&amp;okumenteinstellungen...</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="128"/>
        <source>Pre&amp;ferences...</source>
        <translation>Ein&amp;stellungen...</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="151"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="152"/>
        <source>Zoom &amp;In</source>
        <translation>Ver&amp;größern</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="154"/>
        <source>Zoom &amp;Out</source>
        <translation>Ver&amp;kleinern</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="156"/>
        <source>&amp;Fit to Window</source>
        <translation>An &amp;Fenster anpassen</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="158"/>
        <source>&amp;Actual Size (100 %)</source>
        <translation>&amp;Originalgröße (100 %)</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="163"/>
        <source>&amp;Onion Skin</source>
        <translation>&amp;Zwiebelhaut</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="174"/>
        <source>Onion Skin &amp;Settings...</source>
        <translation>Zwiebelhaut-&amp;Einstellungen...</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="176"/>
        <source>Show &amp;Mesh</source>
        <translation>&amp;Netz anzeigen</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="183"/>
        <source>&amp;Panels</source>
        <translation>&amp;Bedienfelder</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="189"/>
        <source>F&amp;rame</source>
        <translation>&amp;Einzelbild</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="200"/>
        <source>&amp;Object</source>
        <translation>&amp;Objekt</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="210"/>
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="213"/>
        <source>Tools</source>
        <translation>Werkzeuge</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="221"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="222"/>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>&amp;Tastenkürzel</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="224"/>
        <source>&amp;About Finbook</source>
        <translation>Ü&amp;ber Finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="244"/>
        <source>Onion Skin</source>
        <translation>Zwiebelhaut</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="268"/>
        <source>About Finbook</source>
        <translation>Über Finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_menus.cpp" line="269"/>
        <source>&lt;h3&gt;Finbook %1&lt;/h3&gt;&lt;p&gt;A flipbook animation editor: draw frame by frame, and bend drawings with pins.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Finbook %1&lt;/h3&gt;&lt;p&gt;Ein Daumenkino-Animationseditor: Einzelbilder nacheinander zeichnen und Zeichnungen mit Pins verformen.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_deform.cpp" line="27"/>
        <source>&amp;Deform</source>
        <translation>&amp;Verformen</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_deform.cpp" line="36"/>
        <source>Deform</source>
        <translation>Verformen</translation>
    </message>
    <message>
        <location filename="../ui/src/main_window_deform.cpp" line="49"/>
        <source>Preparing the deformation…</source>
        <translation>Verformung wird vorbereitet…</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ObjectActions</name>
    <message>
        <location filename="../ui/src/object_actions.cpp" line="27"/>
        <source>&amp;New Object</source>
        <translation>&amp;Neues Objekt</translation>
    </message>
    <message>
        <location filename="../ui/src/object_actions.cpp" line="29"/>
        <source>&amp;Delete Object</source>
        <translation>Objekt &amp;löschen</translation>
    </message>
    <message>
        <location filename="../ui/src/object_actions.cpp" line="30"/>
        <source>&amp;Merge Objects</source>
        <translation>Objekte &amp;zusammenführen</translation>
    </message>
    <message>
        <location filename="../ui/src/object_actions.cpp" line="33"/>
        <source>Move &amp;Selection to Object</source>
        <translation>&amp;Auswahl in Objekt verschieben</translation>
    </message>
    <message>
        <location filename="../ui/src/object_actions.cpp" line="34"/>
        <source>Bring &amp;Forward</source>
        <translation>Nach &amp;vorne bringen</translation>
    </message>
    <message>
        <location filename="../ui/src/object_actions.cpp" line="36"/>
        <source>Send &amp;Backward</source>
        <translation>Nach &amp;hinten stellen</translation>
    </message>
    <message>
        <location filename="../ui/src/object_actions.cpp" line="38"/>
        <source>&amp;Visible</source>
        <translation>&amp;Sichtbar</translation>
    </message>
    <message>
        <location filename="../ui/src/object_actions.cpp" line="39"/>
        <source>&amp;Locked</source>
        <translation>&amp;Gesperrt</translation>
    </message>
    <message>
        <location filename="../ui/src/object_actions.cpp" line="42"/>
        <source>New object above the current one</source>
        <translation>Neues Objekt über dem aktuellen</translation>
    </message>
    <message>
        <location filename="../ui/src/object_actions.cpp" line="43"/>
        <source>Merge the selected objects, or the current one into the one below</source>
        <translation>Die ausgewählten Objekte zusammenführen oder das aktuelle mit dem darunterliegenden</translation>
    </message>
    <message>
        <location filename="../ui/src/object_actions.cpp" line="44"/>
        <source>Move the selected strokes to another object</source>
        <translation>Die ausgewählten Striche in ein anderes Objekt verschieben</translation>
    </message>
    <message>
        <location filename="../ui/src/object_actions.cpp" line="46"/>
        <source>New</source>
        <translation>Neu</translation>
    </message>
    <message>
        <location filename="../ui/src/object_actions.cpp" line="47"/>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <location filename="../ui/src/object_actions.cpp" line="48"/>
        <source>Merge</source>
        <translation>Zusammenführen</translation>
    </message>
    <message>
        <location filename="../ui/src/object_actions.cpp" line="49"/>
        <source>Move To</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <location filename="../ui/src/object_actions.cpp" line="118"/>
        <source>Object %1</source>
        <translation>Objekt %1</translation>
    </message>
    <message>
        <location filename="../ui/src/object_actions.cpp" line="170"/>
        <source>Merge Objects</source>
        <translation>Objekte zusammenführen</translation>
    </message>
</context>
<context>
    <name>finbook::ui::OnionSkinEditor</name>
    <message>
        <location filename="../ui/src/onion_skin_editor.cpp" line="14"/>
        <source>Show onion skin</source>
        <translation>Zwiebelhaut anzeigen</translation>
    </message>
    <message>
        <location filename="../ui/src/onion_skin_editor.cpp" line="24"/>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <location filename="../ui/src/onion_skin_editor.cpp" line="27"/>
        <source>Frames before:</source>
        <translation>Einzelbilder davor:</translation>
    </message>
    <message>
        <location filename="../ui/src/onion_skin_editor.cpp" line="28"/>
        <source>Frames after:</source>
        <translation>Einzelbilder danach:</translation>
    </message>
    <message>
        <location filename="../ui/src/onion_skin_editor.cpp" line="29"/>
        <source>Opacity of the nearest frame:</source>
        <translation>Deckkraft des nächsten Einzelbilds:</translation>
    </message>
    <message>
        <location filename="../ui/src/onion_skin_editor.cpp" line="30"/>
        <source>Tint before:</source>
        <translation>Tönung davor:</translation>
    </message>
    <message>
        <location filename="../ui/src/onion_skin_editor.cpp" line="31"/>
        <source>Tint after:</source>
        <translation>Tönung danach:</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PenTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tool_pen.h" line="30"/>
        <source>Pen</source>
        <translation>Stift</translation>
    </message>
    <message>
        <location filename="../ui/src/tool_pen.cpp" line="88"/>
        <source>Draw Stroke</source>
        <translation>Strich zeichnen</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PinTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tool_pin.h" line="17"/>
        <source>Pin</source>
        <translation>Pin</translation>
    </message>
    <message>
        <location filename="../ui/src/tool_pin.cpp" line="154"/>
        <source>Click on a visible, unlocked drawing to pin it.</source>
        <translation>Klicken Sie auf eine sichtbare, nicht gesperrte Zeichnung, um einen Pin zu setzen.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PlaybackController</name>
    <message>
        <location filename="../ui/src/playback_controller.cpp" line="64"/>
        <location filename="../ui/src/playback_controller.cpp" line="206"/>
        <source>&amp;Play</source>
        <translation>Abs&amp;pielen</translation>
    </message>
    <message>
        <location filename="../ui/src/playback_controller.cpp" line="68"/>
        <source>Play or pause the animation</source>
        <translation>Animation abspielen oder anhalten</translation>
    </message>
    <message>
        <location filename="../ui/src/playback_controller.cpp" line="76"/>
        <source>&amp;Loop</source>
        <translation>&amp;Endlosschleife</translation>
    </message>
    <message>
        <location filename="../ui/src/playback_controller.cpp" line="80"/>
        <source>Start again at the end of the play range</source>
        <translation>Am Ende des Wiedergabebereichs wieder von vorn beginnen</translation>
    </message>
    <message>
        <location filename="../ui/src/playback_controller.cpp" line="206"/>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PreferencesDialog</name>
    <message>
        <location filename="../ui/src/preferences_dialog.cpp" line="21"/>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <location filename="../ui/src/preferences_dialog.cpp" line="25"/>
        <source>New Documents</source>
        <translation>Neue Dokumente</translation>
    </message>
    <message>
        <location filename="../ui/src/preferences_dialog.cpp" line="26"/>
        <source>Onion Skin</source>
        <translation>Zwiebelhaut</translation>
    </message>
    <message>
        <location filename="../ui/src/preferences_dialog.cpp" line="27"/>
        <source>Keyboard Shortcuts</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <location filename="../ui/src/preferences_dialog.cpp" line="42"/>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <location filename="../ui/src/preferences_dialog.cpp" line="48"/>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <location filename="../ui/src/preferences_dialog.cpp" line="53"/>
        <source>Frame rate:</source>
        <translation>Bildrate:</translation>
    </message>
    <message>
        <location filename="../ui/src/preferences_dialog.cpp" line="54"/>
        <source>Canvas width:</source>
        <translation>Leinwandbreite:</translation>
    </message>
    <message>
        <location filename="../ui/src/preferences_dialog.cpp" line="55"/>
        <source>Canvas height:</source>
        <translation>Leinwandhöhe:</translation>
    </message>
    <message>
        <location filename="../ui/src/preferences_dialog.cpp" line="76"/>
        <source>Conflicting Shortcuts</source>
        <translation>Kollidierende Tastenkürzel</translation>
    </message>
    <message>
        <location filename="../ui/src/preferences_dialog.cpp" line="77"/>
        <source>Two or more actions share a shortcut. Change or clear the shortcuts marked in red, then press OK again.</source>
        <translation>Mehrere Aktionen teilen sich ein Tastenkürzel. Ändern oder löschen Sie die rot markierten Kürzel und drücken Sie erneut OK.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SelectTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tool_select.h" line="28"/>
        <source>Select</source>
        <translation>Auswahl</translation>
    </message>
    <message>
        <location filename="../ui/src/tool_select.cpp" line="264"/>
        <source>The strokes cannot be transformed that far.</source>
        <translation>So weit lassen sich die Striche nicht umformen.</translation>
    </message>
    <message>
        <location filename="../ui/src/tool_select.cpp" line="273"/>
        <source>Move Strokes</source>
        <translation>Striche verschieben</translation>
    </message>
    <message>
        <location filename="../ui/src/tool_select.cpp" line="274"/>
        <source>Rotate Strokes</source>
        <translation>Striche drehen</translation>
    </message>
    <message>
        <location filename="../ui/src/tool_select.cpp" line="275"/>
        <source>Scale Strokes</source>
        <translation>Striche skalieren</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ShortcutEditor</name>
    <message>
        <location filename="../ui/src/shortcut_editor.cpp" line="29"/>
        <source>Action</source>
        <translation>Aktion</translation>
    </message>
    <message>
        <location filename="../ui/src/shortcut_editor.cpp" line="29"/>
        <source>Shortcut</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <location filename="../ui/src/shortcut_editor.cpp" line="47"/>
        <source>Restore Defaults</source>
        <translation>Standardwerte wiederherstellen</translation>
    </message>
    <message>
        <location filename="../ui/src/shortcut_editor.cpp" line="91"/>
        <source>%1 is used by: %2</source>
        <translation>%1 wird verwendet von: %2</translation>
    </message>
    <message>
        <location filename="../ui/src/shortcut_editor.cpp" line="99"/>
        <source>Conflicting shortcuts:</source>
        <translation>Kollidierende Tastenkürzel:</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ShortcutsDialog</name>
    <message>
        <location filename="../ui/src/shortcuts_dialog.cpp" line="15"/>
        <source>Keyboard Shortcuts</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <location filename="../ui/src/shortcuts_dialog.cpp" line="21"/>
        <source>Pan the view</source>
        <translation>Ansicht verschieben</translation>
    </message>
    <message>
        <location filename="../ui/src/shortcuts_dialog.cpp" line="21"/>
        <source>Space + drag, or middle button drag</source>
        <translation>Leertaste + Ziehen oder Ziehen mit mittlerer Maustaste</translation>
    </message>
    <message>
        <location filename="../ui/src/shortcuts_dialog.cpp" line="22"/>
        <source>Zoom about the cursor</source>
        <translation>Um den Mauszeiger zoomen</translation>
    </message>
    <message>
        <location filename="../ui/src/shortcuts_dialog.cpp" line="22"/>
        <source>Mouse wheel</source>
        <translation>Mausrad</translation>
    </message>
    <message>
        <location filename="../ui/src/shortcuts_dialog.cpp" line="26"/>
        <source>Action</source>
        <translation>Aktion</translation>
    </message>
    <message>
        <location filename="../ui/src/shortcuts_dialog.cpp" line="26"/>
        <source>Shortcut</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <location filename="../ui/src/shortcuts_dialog.cpp" line="38"/>
        <source>Filter</source>
        <translation>Filter</translation>
    </message>
</context>
<context>
    <name>finbook::ui::StrokeEraserTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tool_eraser.h" line="17"/>
        <source>Stroke Eraser</source>
        <translation>Strich-Radierer</translation>
    </message>
    <message>
        <location filename="../ui/src/tool_eraser.cpp" line="92"/>
        <source>Erase</source>
        <translation>Radieren</translation>
    </message>
</context>
<context>
    <name>finbook::ui::TimelineWidget</name>
    <message>
        <location filename="../ui/src/timeline_widget.cpp" line="68"/>
        <source>Onion Skin</source>
        <translation>Zwiebelhaut</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline_widget.cpp" line="69"/>
        <source>Show neighbouring frames faintly while drawing</source>
        <translation>Benachbarte Einzelbilder beim Zeichnen blass anzeigen</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline_widget.cpp" line="85"/>
        <source>Before:</source>
        <translation>Davor:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline_widget.cpp" line="86"/>
        <source>How many earlier frames the onion skin shows</source>
        <translation>Wie viele vorherige Einzelbilder die Zwiebelhaut zeigt</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline_widget.cpp" line="87"/>
        <source>After:</source>
        <translation>Danach:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline_widget.cpp" line="88"/>
        <source>How many later frames the onion skin shows</source>
        <translation>Wie viele folgende Einzelbilder die Zwiebelhaut zeigt</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline_widget.cpp" line="116"/>
        <source>Frame %1 of %2 · %3 fps</source>
        <translation>Einzelbild %1 von %2 · %3 fps</translation>
    </message>
</context>
</TS>
