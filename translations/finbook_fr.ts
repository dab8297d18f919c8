<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr_FR">
<context>
    <name>BetweenDrawings</name>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="229"/>
        <source>The first key has no lines to carry.</source>
        <translation>La première clé n’a aucune ligne à transporter.</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="122"/>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="231"/>
        <source>The second key has no lines to fit to.</source>
        <translation>La seconde clé n’a aucune ligne sur laquelle ajuster.</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="243"/>
        <source>The first key could not be meshed: %1</source>
        <translation>La première clé n’a pas pu être maillée : %1</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="279"/>
        <source>The first key&apos;s lines are dots: there is nothing to fit.</source>
        <translation>Les lignes de la première clé sont des points : il n’y a rien à ajuster.</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="291"/>
        <source>The first key&apos;s mesh cannot be fitted: %1</source>
        <translation>Le maillage de la première clé ne peut pas être ajusté : %1</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="89"/>
        <source>The lines of the first key around (%1, %2), %3 × %4 px, find nothing like them in the second key.</source>
        <translation>Les lignes de la première clé autour de (%1, %2), %3 × %4 px, ne trouvent rien de semblable dans la seconde.</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="98"/>
        <source>The first key&apos;s drawing cannot be laid on all of the second&apos;s: its lines around (%1, %2), %3 × %4 px (%5 % of them), have nothing of the first key on them. Draw a key between them, or draw the second closer to the first.</source>
        <translation>Le dessin de la première clé ne se pose pas sur tout le second : ses lignes autour de (%1, %2), %3 × %4 px (%5 % d’entre elles), n’ont rien de la première clé sur elles. Dessinez une clé entre les deux, ou dessinez la seconde plus proche de la première.</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="110"/>
        <source>The two drawings are too different to fit one onto the other (%1 % of the drawing apart on the median, %2 % stretched).%3 Draw a key between them, or draw the second closer to the first.</source>
        <translation>Les deux dessins sont trop différents pour ajuster l’un sur l’autre (à %1 % du dessin en médiane, étiré de %2 %).%3 Dessinez une clé entre les deux, ou la seconde plus proche de la première.</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="120"/>
        <source>A correspondence pin is not on the first key&apos;s drawing.</source>
        <translation>Une épingle de correspondance n’est pas sur le dessin de la première clé.</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="124"/>
        <source>The fit could not be solved.</source>
        <translation>L’ajustement n’a pas pu être résolu.</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="139"/>
        <source>The fitted motion cannot be interpolated: %1</source>
        <translation>Le mouvement ajusté ne peut pas être interpolé : %1</translation>
    </message>
</context>
<context>
    <name>CelEditing</name>
    <message>
        <location filename="../ui/src/layers/cel_editing.cpp" line="113"/>
        <source>Cut Cels</source>
        <translation>Couper les cellulos</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/cel_editing.cpp" line="141"/>
        <source>No cels have been copied.</source>
        <translation>Aucun cellulo n’a été copié.</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/cel_editing.cpp" line="149"/>
        <source>The cels cannot go onto a locked layer.</source>
        <translation>Les cellulos ne peuvent pas aller sur un calque verrouillé.</translation>
    </message>
</context>
<context>
    <name>Command</name>
    <message>
        <location filename="../model/src/commands.cpp" line="24"/>
        <source>Draw Stroke</source>
        <translation>Tracer un trait</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="48"/>
        <source>Erase Stroke</source>
        <translation>Effacer un trait</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="77"/>
        <source>Move Strokes to Object</source>
        <translation>Déplacer les traits vers un objet</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="172"/>
        <source>New Object</source>
        <translation>Nouvel objet</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="200"/>
        <source>Delete Object</source>
        <translation>Supprimer l&apos;objet</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="229"/>
        <source>Rename Object</source>
        <translation>Renommer l&apos;objet</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="254"/>
        <source>Reorder Object</source>
        <translation>Réordonner l&apos;objet</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="285"/>
        <source>Show Object</source>
        <translation>Afficher l&apos;objet</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="285"/>
        <source>Hide Object</source>
        <translation>Masquer l&apos;objet</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="287"/>
        <source>Lock Object</source>
        <translation>Verrouiller l&apos;objet</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="287"/>
        <source>Unlock Object</source>
        <translation>Déverrouiller l&apos;objet</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="321"/>
        <source>Insert Frame</source>
        <translation>Insérer une image</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="325"/>
        <location filename="../model/src/scene/layer_commands.cpp" line="25"/>
        <source>Object</source>
        <translation>Objet</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="346"/>
        <source>Duplicate Frame</source>
        <translation>Dupliquer l&apos;image</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="365"/>
        <location filename="../model/src/scene/layer_commands.cpp" line="413"/>
        <source>Paste Cels</source>
        <translation>Coller les cellulos</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="420"/>
        <source>Delete Frame</source>
        <translation>Supprimer l&apos;image</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="447"/>
        <source>Move Frame</source>
        <translation>Déplacer l&apos;image</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="471"/>
        <source>Change Frame Exposure</source>
        <translation>Modifier l&apos;exposition de l&apos;image</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="515"/>
        <source>Change Document Settings</source>
        <translation>Modifier les paramètres du document</translation>
    </message>
    <message>
        <location filename="../model/src/object_commands.cpp" line="28"/>
        <source>“%1” has lines under the picture of “%2”: one object draws its picture under its lines, so merged they would cover it. Put the picture below them first (Object → Send Backward).</source>
        <translation>« %1 » a des lignes sous l’image de « %2 » : un objet dessine son image sous ses lignes, donc fusionnées elles la couvriraient. Placez d’abord l’image en dessous (Objet → Descendre).</translation>
    </message>
    <message>
        <location filename="../model/src/object_commands.cpp" line="43"/>
        <source>Merge Objects</source>
        <translation>Fusionner les objets</translation>
    </message>
    <message>
        <location filename="../model/src/pins/pin_commands.cpp" line="56"/>
        <source>Add Pin</source>
        <translation>Ajouter une épingle</translation>
    </message>
    <message>
        <location filename="../model/src/pins/pin_commands.cpp" line="64"/>
        <source>Remove Pin</source>
        <translation>Retirer l&apos;épingle</translation>
    </message>
    <message>
        <location filename="../model/src/pins/pin_commands.cpp" line="74"/>
        <source>Move Pin</source>
        <translation>Déplacer l&apos;épingle</translation>
    </message>
    <message>
        <location filename="../model/src/pins/pin_commands.cpp" line="88"/>
        <source>Change Mesh Density</source>
        <translation>Modifier la densité du maillage</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_commands.cpp" line="49"/>
        <source>Place Cage</source>
        <translation>Placer une cage</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_commands.cpp" line="56"/>
        <source>Edit Cage</source>
        <translation>Modifier la cage</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_commands.cpp" line="67"/>
        <source>Move Cage Corners</source>
        <translation>Déplacer les coins de la cage</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_commands.cpp" line="75"/>
        <source>Remove Rig</source>
        <translation>Retirer l&apos;armature</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/inbetween_commands.cpp" line="17"/>
        <location filename="../model/src/inbetween/inbetween_commands.cpp" line="29"/>
        <source>Generate In-betweens</source>
        <translation>Générer des intervalles</translation>
    </message>
    <message>
        <location filename="../model/src/rig/rig_commands.cpp" line="92"/>
        <source>Reset Pose</source>
        <translation>Réinitialiser la pose</translation>
    </message>
    <message>
        <location filename="../model/src/rig/rig_commands.cpp" line="220"/>
        <location filename="../model/src/skeleton/skeleton_join_commands.cpp" line="199"/>
        <source>Apply Pose to Drawing</source>
        <translation>Appliquer la pose au dessin</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="78"/>
        <source>Build Skeleton</source>
        <translation>Construire le squelette</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="89"/>
        <source>Change Skeleton Settings</source>
        <translation>Modifier les réglages du squelette</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="117"/>
        <source>Pose Bones</source>
        <translation>Poser les os</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="126"/>
        <source>Change Skinning</source>
        <translation>Modifier l&apos;habillage</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="143"/>
        <source>Lock Joint</source>
        <translation>Verrouiller l’articulation</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="143"/>
        <source>Unlock Joint</source>
        <translation>Déverrouiller l’articulation</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="170"/>
        <source>Reset Bone Pose</source>
        <translation>Réinitialiser la pose de l’os</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="182"/>
        <source>Move Joint</source>
        <translation>Déplacer l’articulation</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="205"/>
        <source>Insert Joint</source>
        <translation>Insérer une articulation</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="218"/>
        <source>Delete Joint</source>
        <translation>Supprimer l’articulation</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_join_commands.cpp" line="106"/>
        <source>Join Part</source>
        <translation>Joindre la partie</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_join_commands.cpp" line="130"/>
        <source>Detach Part</source>
        <translation>Détacher la partie</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_join_commands.cpp" line="135"/>
        <source>Join Overlapping Parts</source>
        <translation>Joindre les parties qui se chevauchent</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_join_commands.cpp" line="166"/>
        <source>Make Character Root</source>
        <translation>Faire la racine du personnage</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_commands.cpp" line="92"/>
        <source>Recolour Fill</source>
        <translation>Recolorer le remplissage</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_commands.cpp" line="92"/>
        <source>Fill Region</source>
        <translation>Remplir la zone</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_commands.cpp" line="101"/>
        <source>Remove Fill</source>
        <translation>Retirer le remplissage</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_commands.cpp" line="112"/>
        <source>Fill All Enclosed Regions</source>
        <translation>Remplir toutes les zones fermées</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_commands.cpp" line="123"/>
        <source>Close Gaps</source>
        <translation>Fermer les trous</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_commands.cpp" line="18"/>
        <source>Import Sound</source>
        <translation>Importer un son</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_commands.cpp" line="37"/>
        <source>Delete Sound</source>
        <translation>Supprimer le son</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_commands.cpp" line="77"/>
        <source>Move Sound</source>
        <translation>Déplacer le son</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_commands.cpp" line="79"/>
        <source>Change Sound Volume</source>
        <translation>Changer le volume du son</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_commands.cpp" line="83"/>
        <source>Mute Sound</source>
        <translation>Couper le son</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_commands.cpp" line="83"/>
        <source>Unmute Sound</source>
        <translation>Rétablir le son</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_commands.cpp" line="19"/>
        <source>Shade Fills</source>
        <translation>Ombrer les remplissages</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_commands.cpp" line="19"/>
        <source>Unshade Fills</source>
        <translation>Retirer l’ombrage des remplissages</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_commands.cpp" line="46"/>
        <source>Move Light</source>
        <translation>Déplacer la lumière</translation>
    </message>
    <message>
        <location filename="../model/src/erase/stroke_cut.cpp" line="162"/>
        <source>Keep Fills Along a Cut</source>
        <translation>Garder les remplissages le long d’une coupe</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_commands.cpp" line="60"/>
        <source>Change Camera Key</source>
        <translation>Modifier la clé de caméra</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_commands.cpp" line="60"/>
        <source>Add Camera Key</source>
        <translation>Ajouter une clé de caméra</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_commands.cpp" line="66"/>
        <source>Delete Camera Key</source>
        <translation>Supprimer la clé de caméra</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_commands.cpp" line="77"/>
        <source>Move Camera Key</source>
        <translation>Déplacer la clé de caméra</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="17"/>
        <source>New Layer</source>
        <translation>Nouveau calque</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="47"/>
        <source>Duplicate Layer</source>
        <translation>Dupliquer le calque</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="56"/>
        <source>%1 copy</source>
        <translation>%1 copie</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="77"/>
        <source>Delete Layer</source>
        <translation>Supprimer le calque</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="104"/>
        <source>Move Layer</source>
        <translation>Déplacer le calque</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="168"/>
        <source>Insert Time</source>
        <translation>Insérer du temps</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="185"/>
        <source>Delete Time</source>
        <translation>Supprimer du temps</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="222"/>
        <location filename="../model/src/scene/layer_commands.cpp" line="342"/>
        <source>Move Cels</source>
        <translation>Déplacer les cellulos</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="252"/>
        <source>Insert Empty Cel</source>
        <translation>Insérer un cellulo vide</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="342"/>
        <source>Copy Cels</source>
        <translation>Copier les cellulos</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="430"/>
        <source>Delete Cels</source>
        <translation>Supprimer les cellulos</translation>
    </message>
    <message>
        <location filename="../model/src/document.cpp" line="21"/>
        <location filename="../model/src/document.cpp" line="226"/>
        <location filename="../model/src/finbook_file_io.cpp" line="226"/>
        <source>Layer 1</source>
        <translation>Calque 1</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_keys.cpp" line="83"/>
        <source>The object is not swappable: make a mouth chart first (Object &gt; New Mouth Chart).</source>
        <translation>L&apos;objet n&apos;est pas interchangeable : créez d&apos;abord une planche de bouches (Objet &gt; Nouvelle planche de bouches).</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_keys.cpp" line="89"/>
        <source>The set &quot;%1&quot; has no drawings named A to F (the mouth shapes lip sync keys): make a mouth chart, or name its drawings by their shapes.</source>
        <translation>Le jeu « %1 » n&apos;a pas de dessins nommés A à F (les formes de bouche de la synchro labiale) : créez une planche de bouches, ou nommez ses dessins d&apos;après leurs formes.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_keys.cpp" line="96"/>
        <source>There is nothing to key.</source>
        <translation>Il n&apos;y a rien à poser.</translation>
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
        <translation>X (repos)</translation>
    </message>
    <message>
        <location filename="../model/src/swap/mouth_chart.cpp" line="116"/>
        <source>Mouth</source>
        <translation>Bouche</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="64"/>
        <source>Make Object Swappable</source>
        <translation>Rendre l&apos;objet interchangeable</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="90"/>
        <source>New Swap Set</source>
        <translation>Nouveau jeu de dessins</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="139"/>
        <source>Show Drawing &quot;%1&quot;</source>
        <translation>Afficher le dessin « %1 »</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="218"/>
        <source>New Drawing &quot;%1&quot;</source>
        <translation>Nouveau dessin « %1 »</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="270"/>
        <source>Rename Drawing</source>
        <translation>Renommer le dessin</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="300"/>
        <source>Delete Drawing &quot;%1&quot;</source>
        <translation>Supprimer le dessin « %1 »</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="334"/>
        <source>Make Drawing Independent</source>
        <translation>Garder le dessin pour cette image</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_commands.cpp" line="18"/>
        <source>Import Picture</source>
        <translation>Importer une image</translation>
    </message>
    <message>
        <location filename="../model/src/fill/uncovered_lines.cpp" line="266"/>
        <source>Show Lines</source>
        <translation>Afficher les traits</translation>
    </message>
</context>
<context>
    <name>CommandLine</name>
    <message>
        <location filename="../app/cli.cpp" line="193"/>
        <source>No command given; see finbook --help.</source>
        <translation>Aucune commande indiquée ; voir finbook --help.</translation>
    </message>
    <message>
        <location filename="../app/cli.cpp" line="197"/>
        <source>Usage: finbook info FILE</source>
        <translation>Utilisation : finbook info FILE</translation>
    </message>
    <message>
        <location filename="../app/cli.cpp" line="217"/>
        <source>Unknown command &quot;%1&quot;; see finbook --help.</source>
        <translation>Commande inconnue « %1 » ; voir finbook --help.</translation>
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
        <translation>Finbook, un éditeur d&apos;animation en folioscope.

  finbook [FILE]               ouvrir FILE dans l&apos;éditeur
  finbook info FILE            afficher un résumé JSON de FILE
  finbook export FILE OUTDIR   rendre chaque image dans OUTDIR/frame_0001.png ...
  finbook export FILE OUT      exporter vers OUT.gif, .mp4, .webm, .apng ou .html
  finbook export FILE OUT.obj --frame N   l&apos;image N en modèle 3D (OUT.obj, OUT.mtl)
  finbook export FILE OUT.glb --frame N   l&apos;image N en modèle 3D (glTF binaire)
  finbook export FILE... --format F --out-dir DIR   exporter plusieurs fichiers
  finbook thumbnail FILE OUT.png SIZE   écrire la première image en PNG d&apos;au plus SIZE px</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="56"/>
        <source>Use LANGUAGE (e.g. de, en, fr, ja) instead of the system&apos;s.</source>
        <translation>Utiliser la langue LANGUAGE (par ex. de, en, fr, ja) au lieu de celle du système.</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="62"/>
        <source>FILE, or a command.</source>
        <translation>FILE, ou une commande.</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="74"/>
        <source>see finbook --help</source>
        <comment>after an error</comment>
        <translation>voir finbook --help</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="81"/>
        <source>%1; %2.</source>
        <comment>an argument error from Qt, then &quot;see finbook --help&quot;</comment>
        <translation>%1 ; %2.</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="117"/>
        <source>Unknown command &quot;%1&quot;; %2.</source>
        <translation>Commande inconnue « %1 » ; %2.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="43"/>
        <source>export: frames A to B (default: the play range).</source>
        <translation>export : images A à B (par défaut : la plage de lecture).</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="39"/>
        <source>export: png, svg, gif, mp4, webm, apng, html, obj, glb, json (Lottie) or lottie (dotLottie).</source>
        <translation>export : png, svg, gif, mp4, webm, apng, html, obj, glb, json (Lottie) ou lottie (dotLottie).</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="45"/>
        <source>export: frame N only; a 3D model (obj, glb) is one frame, by default the first of the play range.</source>
        <translation>export : l&apos;image N seulement ; un modèle 3D (obj, glb) est une seule image, par défaut la première de la plage de lecture.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="48"/>
        <source>export: multiply the canvas size by S.</source>
        <translation>export : multiplier la taille du canevas par S.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="50"/>
        <source>export: N frames per second (default: the document&apos;s).</source>
        <translation>export : N images par seconde (par défaut : celle du document).</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="52"/>
        <source>export: this background colour (#rrggbb).</source>
        <translation>export : cette couleur d&apos;arrière-plan (#rrggbb).</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="53"/>
        <source>export: no background.</source>
        <translation>export : pas d&apos;arrière-plan.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="55"/>
        <source>export png/svg: one file per drawing plus an exposure sheet.</source>
        <translation>export png/svg : un fichier par dessin, plus une feuille d&apos;exposition.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="58"/>
        <source>export: paint the document&apos;s reference picture or video under the drawing.</source>
        <translation>export : peindre l’image ou la vidéo de référence du document sous le dessin.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="62"/>
        <source>export: the whole page, not the shot the document&apos;s camera frames.</source>
        <translation>export : la page entière, pas le plan que cadre la caméra du document.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="65"/>
        <source>export: only the layers named A, B, ... (hidden ones too), not every visible layer.</source>
        <translation>export : seulement les calques nommés A, B, ... (masqués compris), pas tous les calques visibles.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="69"/>
        <source>export: fail (exit code 2, nothing written) when a sound clip or the reference cannot be used, instead of leaving it out with a warning.</source>
        <translation>export : échouer (code de sortie 2, rien n’est écrit) quand un clip sonore ou la référence ne peut pas être utilisé, au lieu de l’omettre avec un avertissement.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="72"/>
        <source>export: replace existing files.</source>
        <translation>export : remplacer les fichiers existants.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="73"/>
        <source>export: write each FILE into DIR.</source>
        <translation>export : écrire chaque FILE dans DIR.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="75"/>
        <source>export: allow up to N frames (default: 100000 files, 3 hours of video).</source>
        <translation>export : autoriser jusqu’à N images (par défaut : 100000 fichiers, 3 heures de vidéo).</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="107"/>
        <source>--range needs A-B with 1 &lt;= A &lt;= B, not &quot;%1&quot;.</source>
        <translation>--range attend A-B avec 1 &lt;= A &lt;= B, et non « %1 ».</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="121"/>
        <source>--frame and --range cannot be used together.</source>
        <translation>--frame et --range ne peuvent pas être utilisés ensemble.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="124"/>
        <source>--frame needs a frame number from 1, not &quot;%1&quot;.</source>
        <translation>--frame attend un numéro d&apos;image à partir de 1, pas « %1 ».</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="131"/>
        <source>--scale needs a number above 0, not &quot;%1&quot;.</source>
        <translation>--scale attend un nombre supérieur à 0, et non « %1 ».</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="137"/>
        <source>--fps needs a whole number from %1 to %2, not &quot;%3&quot;.</source>
        <translation>--fps attend un nombre entier de %1 à %2, et non « %3 ».</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="145"/>
        <source>--max-frames needs a whole number above 0, not &quot;%1&quot;.</source>
        <translation>--max-frames attend un nombre entier supérieur à 0, et non « %1 ».</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="151"/>
        <source>--background needs a colour such as #ffffff, not &quot;%1&quot;.</source>
        <translation>--background attend une couleur comme #ffffff, et non « %1 ».</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="163"/>
        <source>Unknown export format &quot;%1&quot;; use png, svg, gif, mp4, webm, apng, html, obj, glb, json (Lottie) or lottie (dotLottie).</source>
        <translation>Format d&apos;export inconnu « %1 » ; utilisez png, svg, gif, mp4, webm, apng, html, obj, glb, json (Lottie) ou lottie (dotLottie).</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="186"/>
        <source>Cannot tell the format from &quot;%1&quot;: end it in .gif, .mp4, .webm, .apng, .html, .obj, .glb, .json (Lottie) or .lottie, give a folder for PNG frames, or use --format.</source>
        <translation>Impossible de déduire le format de « %1 » : terminez le nom par .gif, .mp4, .webm, .apng, .html, .obj, .glb, .json (Lottie) ou .lottie, indiquez un dossier pour des images PNG, ou utilisez --format.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="179"/>
        <source>&quot;%1&quot; is a folder, not a %2 file; give a file name, or --format png to write PNG frames into the folder.</source>
        <translation>« %1 » est un dossier, pas un fichier %2 ; donnez un nom de fichier, ou --format png pour écrire des images PNG dans le dossier.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="191"/>
        <source>--format %1 does not match &quot;%2&quot;.</source>
        <translation>--format %1 ne correspond pas à « %2 ».</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="207"/>
        <source>Usage: finbook export FILE OUT, or finbook export FILE... --out-dir DIR</source>
        <translation>Utilisation : finbook export FILE OUT, ou finbook export FILE... --out-dir DIR</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="211"/>
        <source>Usage: finbook export FILE... --out-dir DIR</source>
        <translation>Utilisation : finbook export FILE... --out-dir DIR</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="228"/>
        <source>--layers needs the names of layers, separated by commas.</source>
        <translation>--layers attend des noms de calques séparés par des virgules.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="231"/>
        <source>--transparent and --background cannot be used together.</source>
        <translation>--transparent et --background ne peuvent pas être utilisés ensemble.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="233"/>
        <source>--one-per-drawing is for png and svg exports only.</source>
        <translation>--one-per-drawing ne s&apos;applique qu&apos;aux exports png et svg.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="329"/>
        <source>Could not write &quot;%1&quot;: %2. Nothing was exported.</source>
        <translation>Impossible d&apos;écrire «&#xa0;%1&#xa0;»&#xa0;: %2. Rien n&apos;a été exporté.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="344"/>
        <source>&quot;%1&quot; has no layer named &quot;%2&quot;; its layers are %3. Nothing was exported.</source>
        <translation>« %1 » n’a pas de calque nommé « %2 » ; ses calques sont %3. Rien n’a été exporté.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="360"/>
        <source>Interrupted; nothing was exported.</source>
        <translation>Interrompu ; rien n’a été exporté.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="368"/>
        <source>Use --overwrite to replace it.</source>
        <translation>Utilisez --overwrite pour le remplacer.</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="370"/>
        <source>Use --max-frames N to allow N frames.</source>
        <translation>Utilisez --max-frames N pour autoriser N images.</translation>
    </message>
</context>
<context>
    <name>Deformation</name>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="127"/>
        <source>The object has no strokes to deform.</source>
        <translation>L&apos;objet n&apos;a aucun trait à déformer.</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="134"/>
        <source>This drawing cannot be meshed for deformation: %1</source>
        <translation>Impossible de mailler ce dessin pour le déformer&#xa0;: %1</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="166"/>
        <source>Cancelled.</source>
        <translation>Annulé.</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="217"/>
        <source>The cage changed while it was being prepared.</source>
        <translation>La cage a changé pendant sa préparation.</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="225"/>
        <source>The object has no mesh to deform.</source>
        <translation>L&apos;objet n&apos;a pas de maillage à déformer.</translation>
    </message>
    <message>
        <location filename="../model/src/pins/pin_setup.cpp" line="20"/>
        <source>The pins cannot be solved on this drawing: %1</source>
        <translation>Impossible de calculer la déformation par les épingles sur ce dessin&#xa0;: %1</translation>
    </message>
    <message>
        <location filename="../model/src/pins/pin_setup.cpp" line="49"/>
        <source>The pins could not be solved: %1</source>
        <translation>Le calcul de la déformation par les épingles a échoué&#xa0;: %1</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="248"/>
        <source>The deformation produced invalid points; it was not applied.</source>
        <translation>La déformation a produit des points invalides&#xa0;; elle n&apos;a pas été appliquée.</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_setup.cpp" line="35"/>
        <source>The cage cannot be used: %1</source>
        <translation>Impossible d&apos;utiliser la cage&#xa0;: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/cage/cage_setup.cpp" line="41"/>
        <source>%n stroke point(s) lie outside the cage; move its corners out so it encloses the drawing.</source>
        <translation>
            <numerusform>%n point de trait se trouve hors de la cage&#xa0;; écartez ses coins pour qu&apos;elle entoure le dessin.</numerusform>
            <numerusform>%n points de trait se trouvent hors de la cage&#xa0;; écartez ses coins pour qu&apos;elle entoure le dessin.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_setup.cpp" line="44"/>
        <source>The drawing cannot be bound to the cage: %1</source>
        <translation>Impossible de lier le dessin à la cage&#xa0;: %1</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_setup.cpp" line="59"/>
        <location filename="../model/src/cage/cage_setup.cpp" line="62"/>
        <source>The cage could not be solved: %1</source>
        <translation>Impossible de résoudre la cage&#xa0;: %1</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_setup.cpp" line="72"/>
        <source>This cage cannot be used: %1</source>
        <translation>Cette cage est inutilisable&#xa0;: %1</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_setup.cpp" line="76"/>
        <source>The cage must enclose the whole object: %1</source>
        <translation>La cage doit entourer tout l&apos;objet&#xa0;: %1</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_setup.cpp" line="99"/>
        <source>No cage fits this drawing: %1</source>
        <translation>Aucune cage ne convient à ce dessin&#xa0;: %1</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_build.cpp" line="42"/>
        <source>No skeleton can be built for this drawing: %1</source>
        <translation>Impossible de construire un squelette pour ce dessin&#xa0;: %1</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_build.cpp" line="55"/>
        <source>The object has no strokes to build a skeleton in.</source>
        <translation>L&apos;objet n&apos;a aucun trait dans lequel construire un squelette.</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_build.cpp" line="73"/>
        <location filename="../model/src/skeleton/skeleton_build.cpp" line="88"/>
        <source>No skeleton can be built for this drawing.</source>
        <translation>Impossible de construire un squelette pour ce dessin.</translation>
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
        <translation>Le squelette est endommagé&#xa0;; reconstruisez-le.</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="29"/>
        <source>Reset the pose or apply it to the drawing before editing joints.</source>
        <translation>Réinitialisez la pose ou appliquez-la au dessin avant de modifier les articulations.</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="31"/>
        <source>There is no such joint.</source>
        <translation>Cette articulation n’existe pas.</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="50"/>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="64"/>
        <source>A joint cannot go there.</source>
        <translation>Une articulation ne peut pas aller là.</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="62"/>
        <source>A joint can only be inserted on a bone.</source>
        <translation>Une articulation ne peut être insérée que sur un os.</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="69"/>
        <source>The bone is too short to split.</source>
        <translation>L’os est trop court pour être divisé.</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="102"/>
        <source>A skeleton needs at least one bone.</source>
        <translation>Un squelette a besoin d’au moins un os.</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="34"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="57"/>
        <source>The skeleton cannot be used: %1</source>
        <translation>Impossible d&apos;utiliser le squelette&#xa0;: %1</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="123"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="138"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="168"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="178"/>
        <source>The skeleton cannot skin this drawing: %1</source>
        <translation>Le squelette ne peut pas habiller ce dessin&#xa0;: %1</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="73"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="295"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="299"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="305"/>
        <source>The bones could not be posed: %1</source>
        <translation>Impossible de poser les os&#xa0;: %1</translation>
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
        <translation>la mémoire est insuffisante pour en faire le rendu</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="53"/>
        <source>its folder cannot be created</source>
        <translation>son dossier ne peut pas être créé</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_encoded.cpp" line="169"/>
        <source>ffmpeg finished without writing the %1; nothing was exported.</source>
        <translation>ffmpeg s&apos;est terminé sans écrire le fichier %1&#xa0;; rien n&apos;a été exporté.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_flipbook.cpp" line="168"/>
        <source>Flipbook</source>
        <translation>Folioscope</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_flipbook.cpp" line="180"/>
        <location filename="../model/src/export/export_flipbook.cpp" line="191"/>
        <source>Play</source>
        <translation>Lecture</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_flipbook.cpp" line="182"/>
        <source>Loop</source>
        <translation>Boucle</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_flipbook.cpp" line="185"/>
        <source>Frame</source>
        <translation>Image</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_flipbook.cpp" line="192"/>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="46"/>
        <source>The frame range %1-%2 is not within the animation&apos;s frames 1-%3; choose a range inside it.</source>
        <translation>La plage d&apos;images %1-%2 n&apos;est pas comprise dans les images 1-%3 de l&apos;animation&#xa0;; choisissez une plage à l&apos;intérieur.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="80"/>
        <source>The camera moves while a drawing is held, so one file per drawing cannot show the shot; export one file per frame, or without the camera.</source>
        <translation>La caméra bouge pendant qu’un dessin est tenu : un fichier par dessin ne peut pas montrer le plan ; exportez un fichier par image, ou sans la caméra.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="116"/>
        <source>The animation has no frames to export.</source>
        <translation>L&apos;animation n&apos;a aucune image à exporter.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="118"/>
        <source>The canvas has no size; set one in Document Settings.</source>
        <translation>Le canevas n&apos;a pas de taille&#xa0;; définissez-en une dans Paramètres du document.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="126"/>
        <source>A 3D model holds one frame, not the frames %1-%2; choose a single frame.</source>
        <translation>Un modèle 3D contient une seule image, pas les images %1 à %2 ; choisissez une seule image.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="146"/>
        <source>The scale %1 is not a size a picture can have; choose a scale that gives 1 to %2 pixels a side.</source>
        <translation>L&apos;échelle %1 ne donne pas une taille d&apos;image possible&#xa0;; choisissez une échelle qui donne de 1 à %2 pixels de côté.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="150"/>
        <source>The scale %1 would make a %2 x %3 pixel picture; choose a scale that gives 1 to %4 pixels a side.</source>
        <translation>L&apos;échelle %1 donnerait une image de %2 x %3 pixels&#xa0;; choisissez une échelle qui donne de 1 à %4 pixels de côté.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="163"/>
        <source>The frame rate %1 is not possible; choose %2 to %3 frames per second.</source>
        <translation>La fréquence d&apos;images %1 n&apos;est pas possible&#xa0;; choisissez de %2 à %3 images par seconde.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="171"/>
        <source>%1 video cannot be transparent; choose WebM, APNG, GIF or PNG for a transparent background.</source>
        <translation>Une vidéo %1 ne peut pas être transparente&#xa0;; choisissez WebM, APNG, GIF ou PNG pour un arrière-plan transparent.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="199"/>
        <source>This export would write %1 frames, more than the %2 allowed; nothing was exported.</source>
        <translation>Cet export écrirait %1 images, plus que les %2 autorisées ; rien n’a été exporté.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="206"/>
        <source>This export would write %1 files (%2 playback ticks), more than %3 without your explicit permission; nothing was exported.</source>
        <translation>Cet export écrirait %1 fichiers (%2 pas de lecture), plus de %3 sans votre autorisation explicite ; rien n’a été exporté.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="214"/>
        <source>This export would make %1 hours of animation (%2 frames), more than %3 hours without your explicit permission; nothing was exported.</source>
        <translation>Cet export produirait %1 heures d’animation (%2 images), plus de %3 heures sans votre autorisation explicite ; rien n’a été exporté.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_sequence.cpp" line="68"/>
        <source>&quot;%1&quot; is a folder where a file should go; choose another folder.</source>
        <translation>«&#xa0;%1&#xa0;» est un dossier, à l&apos;emplacement prévu pour un fichier&#xa0;; choisissez un autre dossier.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_sequence.cpp" line="119"/>
        <source>&quot;%1&quot; is a file, not a folder; choose a folder for the %2 files, or remove the file.</source>
        <translation>« %1 » est un fichier, pas un dossier ; choisissez un dossier pour les fichiers %2, ou supprimez le fichier.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_sequence.cpp" line="128"/>
        <source>&quot;%1&quot; is the top folder of the disk; choose or name a folder for the frames, such as &quot;%2&quot;.</source>
        <translation>« %1 » est le dossier racine du disque ; choisissez ou nommez un dossier pour les images, par exemple « %2 ».</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_sequence.cpp" line="137"/>
        <source>the folder cannot be created</source>
        <translation>le dossier ne peut pas être créé</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="23"/>
        <source>&quot;%1&quot; already exists; nothing was exported.</source>
        <translation>«&#xa0;%1&#xa0;» existe déjà&#xa0;; rien n&apos;a été exporté.</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="30"/>
        <source>Could not write &quot;%1&quot;: %2. Nothing was exported; free some disk space or choose another folder, then export again.</source>
        <translation>Impossible d&apos;écrire «&#xa0;%1&#xa0;»&#xa0;: %2. Rien n&apos;a été exporté&#xa0;; libérez de l&apos;espace disque ou choisissez un autre dossier, puis exportez à nouveau.</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="38"/>
        <source>The export was cancelled; nothing was written.</source>
        <translation>L&apos;export a été annulé&#xa0;; rien n&apos;a été écrit.</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="44"/>
        <source>Another export is writing to &quot;%1&quot;; wait until it has finished, or choose another target.</source>
        <translation>Un autre export écrit dans « %1 » ; attendez qu’il soit terminé, ou choisissez une autre destination.</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="113"/>
        <source>&quot;%1&quot; is a folder; give a file name ending in .%2.</source>
        <translation>«&#xa0;%1&#xa0;» est un dossier&#xa0;; indiquez un nom de fichier se terminant par .%2.</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="254"/>
        <source>Choose where to export the animation to.</source>
        <translation>Choisissez où exporter l&apos;animation.</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/export/exporter.cpp" line="268"/>
        <source>%n more sound clip(s) are left out too.</source>
        <translation>
            <numerusform>%n autre clip sonore est aussi omis.</numerusform>
            <numerusform>%n autres clips sonores sont aussi omis.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="275"/>
        <source>Nothing was exported.</source>
        <translation>Rien n’a été exporté.</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_arguments.cpp" line="41"/>
        <source>GIF</source>
        <translation>GIF</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_arguments.cpp" line="70"/>
        <source>MP4 video</source>
        <translation>vidéo MP4</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_arguments.cpp" line="88"/>
        <source>WebM video</source>
        <translation>vidéo WebM</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_arguments.cpp" line="102"/>
        <source>animated PNG</source>
        <translation>PNG animé</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_encoder.cpp" line="175"/>
        <source>Exporting %1 needs the ffmpeg program, which was not found; install it (on Debian: apt install ffmpeg) and export again.</source>
        <translation>L&apos;export en %1 nécessite le programme ffmpeg, qui est introuvable&#xa0;; installez-le (sous Debian&#xa0;: apt install ffmpeg) et exportez à nouveau.</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_encoder.cpp" line="268"/>
        <source>it stopped unexpectedly</source>
        <translation>il s&apos;est arrêté de façon inattendue</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_encoder.cpp" line="269"/>
        <source>exit code %1</source>
        <translation>code de sortie %1</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_encoder.cpp" line="272"/>
        <source>ffmpeg could not make the %1 (%2); nothing was written. If the disk is full, free some space and export again.</source>
        <translation>ffmpeg n&apos;a pas pu créer le fichier %1 (%2)&#xa0;; rien n&apos;a été écrit. Si le disque est plein, libérez de l&apos;espace et exportez à nouveau.</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/export/ffmpeg_encoder.cpp" line="283"/>
        <source>ffmpeg made no progress for %n second(s) and was stopped; nothing was written. Check that ffmpeg works, then export again.</source>
        <translation>
            <numerusform>ffmpeg n’a pas progressé pendant %n seconde et a été arrêté ; rien n’a été écrit. Vérifiez que ffmpeg fonctionne, puis exportez à nouveau.</numerusform>
            <numerusform>ffmpeg n’a pas progressé pendant %n secondes et a été arrêté ; rien n’a été écrit. Vérifiez que ffmpeg fonctionne, puis exportez à nouveau.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/export/pending_output.cpp" line="341"/>
        <source>a folder cannot be created in it</source>
        <translation>aucun dossier ne peut y être créé</translation>
    </message>
    <message>
        <location filename="../model/src/export/pending_output.cpp" line="362"/>
        <source>&quot;%1&quot; is a folder where a file should go</source>
        <translation>« %1 » est un dossier là où un fichier doit aller</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_model.cpp" line="68"/>
        <source>The 3D model of frame %1 would have more than %L2 vertices, the most a 3D export writes (about 25 MB of glTF). Nothing was exported; lower the mesh density of its objects (Deform → Mesh Density) or hide some of them.</source>
        <translation>Le modèle 3D de l’image %1 aurait plus de %L2 sommets, le maximum qu’un export 3D écrit (environ 25 Mo de glTF). Rien n’a été exporté ; baissez la densité du maillage de ses objets (Déformer → Densité du maillage) ou masquez-en quelques-uns.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_model.cpp" line="79"/>
        <source>Frame %1 shows no drawing to make a 3D model of; choose another frame.</source>
        <translation>L&apos;image %1 ne montre aucun dessin dont faire un modèle 3D ; choisissez une autre image.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_model.cpp" line="84"/>
        <source>No object of frame %1 can be made 3D: their points lie more than %L2 pixels from the page, too far out to mesh. Nothing was exported; move the drawing back onto the page or choose another frame.</source>
        <translation>Aucun objet de l’image %1 ne peut être mis en 3D : leurs points sont à plus de %L2 pixels de la page, trop loin pour être maillés. Rien n’a été exporté ; ramenez le dessin sur la page ou choisissez une autre image.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_model.cpp" line="92"/>
        <source>No object of frame %1 can be made 3D: each is a dot or a straight line, with no area to inflate, or lies too far from the page to mesh. Nothing was exported; draw a shape or choose another frame.</source>
        <translation>Aucun objet de l’image %1 ne peut être mis en 3D : chacun est un point ou une ligne droite, sans surface à gonfler, ou se trouve trop loin de la page pour être maillé. Rien n’a été exporté ; dessinez une forme ou choisissez une autre image.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_model.cpp" line="99"/>
        <source>No object of frame %1 can be made 3D: each is a dot or a straight line, with no area to inflate. Nothing was exported; draw a shape or choose another frame.</source>
        <translation>Aucun objet de l&apos;image %1 ne peut être mis en 3D : chacun est un point ou une ligne droite, sans surface à gonfler. Rien n&apos;a été exporté ; dessinez une forme ou choisissez une autre image.</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/export/export_model.cpp" line="110"/>
        <source>%n object(s) of frame %1 could not be made 3D (a dot or a straight line has no area to inflate; a drawing far off the page cannot be meshed) and were left out.</source>
        <translation>
            <numerusform>%n objet de l’image %1 n’a pas pu être mis en 3D (un point ou une ligne droite n’a pas de surface à gonfler ; un dessin loin hors de la page ne peut pas être maillé) et a été laissé de côté.</numerusform>
            <numerusform>%n objets de l’image %1 n’ont pas pu être mis en 3D (un point ou une ligne droite n’a pas de surface à gonfler ; un dessin loin hors de la page ne peut pas être maillé) et ont été laissés de côté.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/export/export_obj.cpp" line="187"/>
        <source>&quot;%1&quot; would be overwritten by its own material file; give a file name ending in .obj.</source>
        <translation>« %1 » serait écrasé par son propre fichier de matériaux ; donnez un nom de fichier terminé par .obj.</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/export/export_model.cpp" line="115"/>
        <source>%n object(s) of frame %1 could not be made 3D (a dot or a straight line has no area to inflate) and were left out.</source>
        <translation>
            <numerusform>%n objet de l&apos;image %1 n&apos;a pas pu être mis en 3D (un point ou une ligne droite n&apos;a pas de surface à gonfler) et a été omis.</numerusform>
            <numerusform>%n objets de l&apos;image %1 n&apos;ont pas pu être mis en 3D (un point ou une ligne droite n&apos;a pas de surface à gonfler) et ont été omis.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/export/export_glb.cpp" line="48"/>
        <source>Frame %1 makes a 3D model larger than a glTF file can hold (4 GiB); export it as OBJ instead.</source>
        <translation>L&apos;image %1 donne un modèle 3D plus grand que ce qu&apos;un fichier glTF peut contenir (4 Gio) ; exportez-la plutôt en OBJ.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_sound.cpp" line="76"/>
        <source>The sound &quot;%1&quot; is left out: %2</source>
        <translation>Le son « %1 » est omis : %2</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_export.cpp" line="18"/>
        <source>The reference &quot;%1&quot; is left out: %2</source>
        <translation>La référence « %1 » est omise : %2</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_lottie.cpp" line="759"/>
        <source>the zip container failed</source>
        <translation>le conteneur zip n&apos;a pas pu être écrit</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_lottie.cpp" line="775"/>
        <source>Lottie has no place for the reference picture; it is left out.</source>
        <translation>Lottie ne peut pas contenir l&apos;image de référence ; elle est laissée de côté.</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_lottie.cpp" line="777"/>
        <source>Lottie carries no sound; the soundtrack is left out.</source>
        <translation>Lottie ne contient pas de son ; la bande son est laissée de côté.</translation>
    </message>
</context>
<context>
    <name>ExportDone</name>
    <message>
        <location filename="../ui/src/export/export_done.cpp" line="26"/>
        <source>Export Finished</source>
        <translation>Exportation terminée</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_done.cpp" line="31"/>
        <source>Show in Folder</source>
        <translation>Afficher dans le dossier</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_done.cpp" line="38"/>
        <source>Open in Browser</source>
        <translation>Ouvrir dans le navigateur</translation>
    </message>
</context>
<context>
    <name>FileMessages</name>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="17"/>
        <source>The file is not there any more: it may have been moved, renamed or deleted.</source>
        <translation>Le fichier n&apos;est plus là&#xa0;: il a peut-être été déplacé, renommé ou supprimé.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="21"/>
        <source>This is a folder, not an animation. Choose a file ending in .finbook.</source>
        <translation>Ceci est un dossier, pas une animation. Choisissez un fichier se terminant par .finbook.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="23"/>
        <source>This is a device or a pipe, not an animation. Choose a file ending in .finbook.</source>
        <translation>Ceci est un périphérique ou un tube, pas une animation. Choisissez un fichier se terminant par .finbook.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="26"/>
        <source>You are not allowed to read this file. Ask whoever owns it to share it with you, or open a copy of it.</source>
        <translation>Vous n&apos;avez pas le droit de lire ce fichier. Demandez à son propriétaire de le partager avec vous, ou ouvrez-en une copie.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="29"/>
        <source>The disk could not read the file. If it is on a removable drive or a network folder, check that it is still connected.</source>
        <translation>Le disque n&apos;a pas pu lire le fichier. S&apos;il se trouve sur un support amovible ou dans un dossier réseau, vérifiez qu&apos;il est toujours connecté.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="33"/>
        <source>The file is empty: there is no drawing in it.</source>
        <translation>Le fichier est vide&#xa0;: il ne contient aucun dessin.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="34"/>
        <source>This is not a Finbook animation. Choose a file ending in .finbook.</source>
        <translation>Ce n&apos;est pas une animation Finbook. Choisissez un fichier se terminant par .finbook.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="37"/>
        <source>It was saved by a newer version of Finbook. Install that version to open it.</source>
        <translation>Il a été enregistré par une version plus récente de Finbook. Installez cette version pour l&apos;ouvrir.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="40"/>
        <source>The file is damaged near the end: it looks cut off. Perhaps a copy or a save was interrupted.</source>
        <translation>Le fichier est endommagé vers la fin&#xa0;: il semble tronqué. Une copie ou un enregistrement a peut-être été interrompu.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="43"/>
        <source>The file is damaged, or too large for this computer: it asks for more memory than Finbook can use.</source>
        <translation>Le fichier est endommagé, ou trop volumineux pour cet ordinateur&#xa0;: il demande plus de mémoire que Finbook ne peut en utiliser.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="46"/>
        <source>The file is damaged: some of it changed after it was saved. Finbook can open what is still readable.</source>
        <translation>Le fichier est endommagé&#xa0;: une partie a changé après son enregistrement. Finbook peut ouvrir ce qui reste lisible.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="50"/>
        <source>This computer has not enough free memory to open the file. Close other programs or documents and try again.</source>
        <translation>Cet ordinateur n&apos;a pas assez de mémoire libre pour ouvrir le fichier. Fermez d&apos;autres programmes ou documents et réessayez.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="57"/>
        <source>The file is damaged: part of it cannot be read.</source>
        <translation>Le fichier est endommagé&#xa0;: une partie ne peut pas être lue.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="64"/>
        <source>Finbook cannot open “%1”.</source>
        <translation>Finbook ne peut pas ouvrir «&#xa0;%1&#xa0;».</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="68"/>
        <source>Finbook kept the version saved before it as “%1” in the same folder: open that one to get your work back.</source>
        <translation>Finbook a conservé la version enregistrée précédemment sous le nom «&#xa0;%1&#xa0;», dans le même dossier&#xa0;: ouvrez-la pour récupérer votre travail.</translation>
    </message>
</context>
<context>
    <name>FinbookFile</name>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="30"/>
        <source>layer %1</source>
        <translation>calque %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="32"/>
        <source>frame %1</source>
        <translation>image %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="35"/>
        <source>, object &quot;%1&quot;</source>
        <translation>, objet «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="36"/>
        <source>, object %1</source>
        <translation>, objet %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="38"/>
        <source>, stroke %1</source>
        <translation>, trait %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="42"/>
        <source>stroke data %1</source>
        <translation>données de trait %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="44"/>
        <source>pose %1</source>
        <translation>pose %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="85"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="65"/>
        <source>%1: %2</source>
        <translation>%1&#xa0;: %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="93"/>
        <source>%1 runs past the end of its record (%2 bytes needed, %3 left), so a length in the file is wrong</source>
        <translation>%1 dépasse la fin de son enregistrement (%2 octets nécessaires, %3 restants)&#xa0;: une longueur dans le fichier est donc fausse</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="100"/>
        <source>the file ends inside %1 (%2 bytes needed, %3 left)</source>
        <translation>le fichier s&apos;arrête dans %1 (%2 octets nécessaires, %3 restants)</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="116"/>
        <source>%1 claims %2 entries but only %3 bytes remain</source>
        <translation>%1 annonce %2 entrées, mais il ne reste que %3 octets</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="142"/>
        <source>%1 has %2 unexpected bytes at its end</source>
        <translation>%1 se termine par %2 octets inattendus</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="36"/>
        <source>%1 The file is incomplete (perhaps an interrupted copy or save); if there is a backup with the same name ending in ~, open that instead.</source>
        <translation>%1 Le fichier est incomplet (copie ou enregistrement interrompu&#xa0;?)&#xa0;; s&apos;il existe une sauvegarde du même nom terminée par ~, ouvrez-la plutôt.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="42"/>
        <source>%1 The file is damaged; if there is a backup with the same name ending in ~, open that instead.</source>
        <translation>%1 Le fichier est endommagé&#xa0;; s&apos;il existe une sauvegarde du même nom terminée par ~, ouvrez-la plutôt.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="47"/>
        <source>%1 The file is damaged; Finbook can open what is still readable of it, or open the backup with the same name ending in ~ if there is one.</source>
        <translation>%1 Le fichier est endommagé&#xa0;; Finbook peut en ouvrir ce qui reste lisible, ou vous pouvez ouvrir la sauvegarde du même nom terminée par ~, s&apos;il en existe une.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="52"/>
        <source>%1 Close other programs or documents and try again.</source>
        <translation>%1 Fermez d&apos;autres programmes ou documents et réessayez.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="75"/>
        <source>Could not save &quot;%1&quot;: %2. The previous file is unchanged; free some disk space or choose another folder, then save again.</source>
        <translation>Impossible d&apos;enregistrer «&#xa0;%1&#xa0;»&#xa0;: %2. Le fichier précédent n&apos;a pas été modifié&#xa0;; libérez de l&apos;espace disque ou choisissez un autre dossier, puis enregistrez à nouveau.</translation>
    </message>
    <message>
        <location filename="../model/src/io/atomic_file.cpp" line="249"/>
        <source>the backup &quot;%1&quot; cannot be written (%2)</source>
        <translation>la sauvegarde «&#xa0;%1&#xa0;» ne peut pas être écrite (%2)</translation>
    </message>
    <message>
        <location filename="../model/src/io/atomic_file.cpp" line="350"/>
        <source>the disk is full</source>
        <translation>le disque est plein</translation>
    </message>
    <message>
        <location filename="../model/src/io/atomic_file.cpp" line="352"/>
        <source>the disk is read-only</source>
        <translation>le disque est en lecture seule</translation>
    </message>
    <message>
        <location filename="../model/src/io/atomic_file.cpp" line="354"/>
        <source>you do not have permission to write in the folder &quot;%1&quot;</source>
        <translation>vous n&apos;avez pas le droit d&apos;écrire dans le dossier «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <location filename="../model/src/io/atomic_file.cpp" line="357"/>
        <source>the folder &quot;%1&quot; does not exist</source>
        <translation>le dossier «&#xa0;%1&#xa0;» n&apos;existe pas</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="81"/>
        <source>Could not save &quot;%1&quot;: %2. The previous file is unchanged; choose another folder, then save again.</source>
        <translation>Impossible d&apos;enregistrer «&#xa0;%1&#xa0;»&#xa0;: %2. Le fichier précédent n&apos;a pas été modifié&#xa0;; choisissez un autre dossier, puis enregistrez à nouveau.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="91"/>
        <source>Cannot open &quot;%1&quot;: %2. Check that the file exists and that you may read it.</source>
        <translation>Impossible d&apos;ouvrir «&#xa0;%1&#xa0;»&#xa0;: %2. Vérifiez que le fichier existe et que vous avez le droit de le lire.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="132"/>
        <source>it is a folder</source>
        <translation>c&apos;est un dossier</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="165"/>
        <source>Cannot read &quot;%1&quot;: %2.</source>
        <translation>Impossible de lire «&#xa0;%1&#xa0;»&#xa0;: %2.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="146"/>
        <location filename="../model/src/finbook_file_io.cpp" line="176"/>
        <source>Cannot open &quot;%1&quot;. %2</source>
        <translation>Impossible d&apos;ouvrir «&#xa0;%1&#xa0;». %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="136"/>
        <source>Cannot open &quot;%1&quot;: it is a device, a pipe or a socket, not a file. Choose a .finbook file.</source>
        <translation>Impossible d&apos;ouvrir «&#xa0;%1&#xa0;»&#xa0;: c&apos;est un périphérique, un tube ou un socket, pas un fichier. Choisissez un fichier .finbook.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="155"/>
        <source>Cannot open &quot;%1&quot;: there is not enough memory for its %2 MB. Close other programs or documents and try again.</source>
        <translation>Impossible d&apos;ouvrir «&#xa0;%1&#xa0;»&#xa0;: la mémoire est insuffisante pour ses %2&#xa0;Mo. Fermez d&apos;autres programmes ou documents et réessayez.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="266"/>
        <source>Could not save &quot;%1&quot;: the drawing holds invalid data (%2). The previous file is unchanged.</source>
        <translation>Impossible d&apos;enregistrer «&#xa0;%1&#xa0;»&#xa0;: le dessin contient des données invalides (%2). Le fichier précédent n&apos;a pas été modifié.</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="44"/>
        <source>unknown %1 %2</source>
        <translation>%1 %2 de type inconnu</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="47"/>
        <source>it holds data (&quot;%1&quot;) that this version of Finbook does not know, so it was probably made by a newer Finbook; please update Finbook to open it</source>
        <translation>il contient des données («&#xa0;%1&#xa0;») que cette version de Finbook ne connaît pas&#xa0;; il a sans doute été créé par une version plus récente. Mettez Finbook à jour pour l&apos;ouvrir</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="67"/>
        <source>more problems were found and repaired the same way</source>
        <translation>d&apos;autres problèmes ont été trouvés et réparés de la même façon</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="76"/>
        <source>it describes more than a file of its size can hold (opening it would take more than %1 MB of memory)</source>
        <translation>il décrit plus de données qu&apos;un fichier de cette taille ne peut en contenir (l&apos;ouvrir demanderait plus de %1&#xa0;Mo de mémoire)</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="45"/>
        <source>its format version %1 is not one any Finbook writes (this version reads %2 to %3), so the version number is damaged</source>
        <translation>sa version de format %1 n&apos;est écrite par aucun Finbook (cette version lit de %2 à %3)&#xa0;: le numéro de version est donc endommagé</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="55"/>
        <source>the file is empty</source>
        <translation>le fichier est vide</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="57"/>
        <source>the file header</source>
        <translation>l&apos;en-tête du fichier</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="59"/>
        <source>it is not a Finbook animation</source>
        <translation>ce n&apos;est pas une animation Finbook</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="61"/>
        <source>the file ends inside its header</source>
        <translation>le fichier s&apos;arrête au milieu de son en-tête</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="62"/>
        <source>the format version</source>
        <translation>la version du format</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="67"/>
        <source>it was made by a newer version of Finbook (file format %1; this version reads up to %2); please update Finbook to open it</source>
        <translation>il a été créé par une version plus récente de Finbook (format de fichier %1&#xa0;; cette version lit jusqu&apos;au format %2). Mettez Finbook à jour pour l&apos;ouvrir</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="113"/>
        <source>the file&apos;s section list</source>
        <translation>la liste des sections du fichier</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="116"/>
        <source>the file ends before its end</source>
        <translation>le fichier s&apos;arrête avant sa fin prévue</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="120"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="121"/>
        <source>a section header</source>
        <translation>un en-tête de section</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="122"/>
        <source>section %1</source>
        <translation>section %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="141"/>
        <source>the file&apos;s end is damaged</source>
        <translation>la fin du fichier est endommagée</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="146"/>
        <source>its length (%1 bytes) runs past the end of the file (%2 bytes left), yet the file ends with its end marker, so the length is damaged</source>
        <translation>sa longueur (%1 octets) dépasse la fin du fichier (%2 octets restants), alors que le fichier se termine par sa marque de fin&#xa0;: la longueur est donc endommagée</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="154"/>
        <source>the file ends inside this section (%1 bytes announced, %2 left)</source>
        <translation>le fichier s&apos;arrête au milieu de cette section (%1 octets annoncés, %2 restants)</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="158"/>
        <source>the file ends inside this section; what it holds is read</source>
        <translation>le fichier s&apos;arrête au milieu de cette section&#xa0;; ce qu&apos;elle contient est lu</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="162"/>
        <source>a section</source>
        <translation>une section</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="166"/>
        <source>the file ends before this section&apos;s checksum</source>
        <translation>le fichier s&apos;arrête avant la somme de contrôle de cette section</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="168"/>
        <source>a section checksum</source>
        <translation>une somme de contrôle de section</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="171"/>
        <source>its checksum does not match, so its bytes changed after it was saved</source>
        <translation>sa somme de contrôle ne correspond pas, ses octets ont donc changé après l&apos;enregistrement</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="178"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="281"/>
        <source>section %1 is missing</source>
        <translation>la section %1 est absente</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="180"/>
        <source>the end marker</source>
        <translation>le marqueur de fin</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="181"/>
        <source>the file</source>
        <translation>le fichier</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="217"/>
        <source>a sound clip comes before the frames</source>
        <translation>un extrait sonore précède les images</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="224"/>
        <source>the layers come before the frames</source>
        <translation>les calques viennent avant les images</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="226"/>
        <source>the layers are repeated</source>
        <translation>les calques sont répétés</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="235"/>
        <source>the pictures come before the frames</source>
        <translation>les images viennent avant les dessins</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="237"/>
        <source>the pictures are repeated</source>
        <translation>les images sont répétées</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="246"/>
        <source>the camera comes before the frames</source>
        <translation>la caméra vient avant les images</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="248"/>
        <source>the camera is repeated</source>
        <translation>la caméra est répétée</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="257"/>
        <source>the swap sets come before the frames</source>
        <translation>les jeux de dessins précèdent les images</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="259"/>
        <source>the swap sets are repeated</source>
        <translation>les jeux de dessins sont répétés</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="267"/>
        <source>an unknown section is left out</source>
        <translation>une section inconnue est ignorée</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="269"/>
        <source>section</source>
        <translation>section</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="276"/>
        <source>the section is repeated or out of order</source>
        <translation>la section est répétée ou mal placée</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="290"/>
        <source>the palette</source>
        <translation>la palette</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="318"/>
        <source>the end of the section could not be read</source>
        <translation>la fin de la section n&apos;a pas pu être lue</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="319"/>
        <source>the section</source>
        <translation>la section</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="329"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="391"/>
        <source>the document settings</source>
        <translation>les paramètres du document</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="332"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="333"/>
        <source>the canvas size</source>
        <translation>la taille du canevas</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="337"/>
        <source>the canvas size %1×%2 is outside 1 to %3 pixels</source>
        <translation>la taille du canevas %1×%2 n&apos;est pas comprise entre 1 et %3 pixels</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="343"/>
        <source>the background colour</source>
        <translation>la couleur d&apos;arrière-plan</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="344"/>
        <source>the frame rate</source>
        <translation>la fréquence d&apos;images</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="348"/>
        <source>the frame rate %1 is outside %2 to %3</source>
        <translation>la fréquence d&apos;images %1 n&apos;est pas comprise entre %2 et %3</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="354"/>
        <source>the loop flag</source>
        <translation>l&apos;indicateur de boucle</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="357"/>
        <source>the loop flag %1 is neither 0 nor 1</source>
        <translation>l&apos;indicateur de boucle %1 ne vaut ni 0 ni 1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="359"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="360"/>
        <source>the play range</source>
        <translation>la plage de lecture</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="364"/>
        <source>the play range %1 to %2 is invalid</source>
        <translation>la plage de lecture de %1 à %2 est invalide</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="368"/>
        <source>the next id</source>
        <translation>le prochain identifiant</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="370"/>
        <source>the close-gap setting</source>
        <translation>le réglage de fermeture des trous</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="373"/>
        <source>the close-gap setting %1 is outside 0 to %2 pixels</source>
        <translation>le réglage de fermeture des trous %1 n&apos;est pas entre 0 et %2 pixels</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="382"/>
        <source>the next free id %1 is larger than any id can be</source>
        <translation>le prochain identifiant libre %1 dépasse la valeur maximale d&apos;un identifiant</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="421"/>
        <source>its parts are joined in a way too costly to work out</source>
        <translation>ses parties sont jointes d&apos;une façon trop coûteuse à résoudre</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="58"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="60"/>
        <source>the frame list</source>
        <translation>la liste des images</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="68"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="74"/>
        <source>a frame</source>
        <translation>une image</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="71"/>
        <source>the frame is cut off and is left out, with any after it</source>
        <translation>l&apos;image est tronquée et est ignorée, ainsi que toutes celles qui la suivent</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="80"/>
        <source>%1; the frame is left out</source>
        <translation>%1&#xa0;; l&apos;image est ignorée</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="89"/>
        <source>a frame id</source>
        <translation>un identifiant d&apos;image</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="90"/>
        <source>the frame</source>
        <translation>l&apos;image</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="91"/>
        <source>a frame hold</source>
        <translation>une durée d&apos;exposition</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="95"/>
        <source>the hold %1 is outside 1 to %2</source>
        <translation>la durée d&apos;exposition %1 n&apos;est pas comprise entre 1 et %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="97"/>
        <source>the object list</source>
        <translation>la liste des objets</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="104"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="110"/>
        <source>an object</source>
        <translation>un objet</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="107"/>
        <source>the object is cut off and is left out, with any after it</source>
        <translation>l&apos;objet est tronqué et est ignoré, ainsi que tous ceux qui le suivent</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="116"/>
        <source>%1; the object is left out</source>
        <translation>%1&#xa0;; l&apos;objet est ignoré</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="121"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="122"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="212"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="213"/>
        <source>a chunk header</source>
        <translation>un en-tête de bloc</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="123"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="214"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="232"/>
        <source>a chunk</source>
        <translation>un bloc</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="124"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="222"/>
        <source>chunk</source>
        <translation>bloc</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="132"/>
        <source>an object id</source>
        <translation>un identifiant d&apos;objet</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="133"/>
        <source>the object</source>
        <translation>l&apos;objet</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="134"/>
        <source>the object flags</source>
        <translation>les attributs de l&apos;objet</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="137"/>
        <source>the object flags 0x%1 are unknown</source>
        <translation>les attributs d&apos;objet 0x%1 sont inconnus</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="140"/>
        <source>the mesh density</source>
        <translation>la densité du maillage</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="143"/>
        <source>the mesh density %1 is not a number from 0 to 1000</source>
        <translation>la densité du maillage %1 n&apos;est pas un nombre compris entre 0 et 1000</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="160"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="166"/>
        <source>the object name</source>
        <translation>le nom de l&apos;objet</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="163"/>
        <source>the object name is %1 bytes long (at most %2)</source>
        <translation>le nom de l&apos;objet fait %1 octets (%2 au maximum)</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="174"/>
        <source>the object name is not valid UTF-8 text</source>
        <translation>le nom de l&apos;objet n&apos;est pas un texte UTF-8 valide</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="181"/>
        <source>the stroke list</source>
        <translation>la liste des traits</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="188"/>
        <source>a stroke id</source>
        <translation>un identifiant de trait</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="199"/>
        <source>the stroke</source>
        <translation>le trait</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="341"/>
        <source>its pose has %n stroke(s) but the object has %1</source>
        <translation>
            <numerusform>sa pose a %n trait, mais l&apos;objet en a %1</numerusform>
            <numerusform>sa pose a %n traits, mais l&apos;objet en a %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="348"/>
        <source>stroke %1 has %n point(s) but its pose has %2</source>
        <translation>
            <numerusform>le trait %1 a %n point, mais sa pose en a %2</numerusform>
            <numerusform>le trait %1 a %n points, mais sa pose en a %2</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="189"/>
        <source>a stroke reference</source>
        <translation>une référence de trait</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="49"/>
        <source>%1 claims %2 entries; the %3 that fit are read</source>
        <translation>%1 annonce %2 entrées&#xa0;; seules les %3 qui tiennent dans le fichier sont lues</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="192"/>
        <source>it refers to stroke data %1 of %2</source>
        <translation>il renvoie aux données de trait %1, mais il n&apos;y en a que %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="220"/>
        <source>an unknown chunk is left out</source>
        <translation>un bloc inconnu est ignoré</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="227"/>
        <source>chunk %1 appears twice or with another rig</source>
        <translation>le bloc %1 apparaît deux fois ou avec une autre armature</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="236"/>
        <source>%1; the chunk is left out</source>
        <translation>%1&#xa0;; le bloc est ignoré</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="264"/>
        <source>the skeleton&apos;s join</source>
        <translation>la jonction du squelette</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="266"/>
        <source>a join comes without a skeleton</source>
        <translation>une jonction est présente sans squelette</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="274"/>
        <source>the skeleton&apos;s join is damaged</source>
        <translation>la jonction du squelette est endommagée</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="287"/>
        <source>the pin list</source>
        <translation>la liste des épingles</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="292"/>
        <source>a pin id</source>
        <translation>un identifiant d&apos;épingle</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="293"/>
        <source>pin %1</source>
        <translation>l&apos;épingle %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="296"/>
        <source>a pin position</source>
        <translation>une position d&apos;épingle</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="299"/>
        <source>pin %1 has a non-finite position</source>
        <translation>l&apos;épingle %1 a une position non finie</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="310"/>
        <source>the cage corner list</source>
        <translation>la liste des coins de la cage</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="312"/>
        <source>the cage has fewer than 3 corners</source>
        <translation>la cage a moins de 3 coins</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="319"/>
        <source>a cage corner</source>
        <translation>un coin de cage</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="322"/>
        <source>cage corner %1 has a non-finite position</source>
        <translation>le coin de cage %1 a une position non finie</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="331"/>
        <source>a pose reference</source>
        <translation>une référence de pose</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="333"/>
        <source>its pose refers to pose %1 of %2</source>
        <translation>sa pose renvoie à la pose %1, mais il n&apos;y en a que %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="337"/>
        <source>its pose: %1</source>
        <translation>sa pose&#xa0;: %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="360"/>
        <source>%1 has no id</source>
        <translation>%1 n&apos;a pas d&apos;identifiant</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="361"/>
        <source>%1 has the id %2, larger than any id can be</source>
        <translation>%1 a l&apos;identifiant %2, qui dépasse la valeur maximale d&apos;un identifiant</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="369"/>
        <source>%1 has the id %2, which is already used</source>
        <translation>%1 a l&apos;identifiant %2, qui est déjà utilisé</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="449"/>
        <source>the next free id %1 is not above the largest id %2</source>
        <translation>le prochain identifiant libre %1 n&apos;est pas supérieur au plus grand identifiant %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="467"/>
        <source>the id %1 is used twice</source>
        <translation>l&apos;identifiant %1 est utilisé deux fois</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="472"/>
        <source>no frame of it could be read; there is nothing to recover</source>
        <translation>aucune de ses images n&apos;a pu être lue&#xa0;; il n&apos;y a rien à récupérer</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="481"/>
        <source>there is not enough memory to open this file</source>
        <translation>la mémoire est insuffisante pour ouvrir ce fichier</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="26"/>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="28"/>
        <source>a stroke</source>
        <translation>un trait</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="32"/>
        <source>point %1 has a non-finite coordinate</source>
        <translation>le point %1 a une coordonnée non finie</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="48"/>
        <source>%n point(s) with a non-finite coordinate are left out</source>
        <translation>
            <numerusform>%n point avec une coordonnée non finie est ignoré</numerusform>
            <numerusform>%n points avec une coordonnée non finie sont ignorés</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="57"/>
        <source>the stroke table</source>
        <translation>la table des traits</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="71"/>
        <source>a stroke colour</source>
        <translation>une couleur de trait</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="72"/>
        <source>a stroke width</source>
        <translation>une épaisseur de trait</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="74"/>
        <source>the width %1 is not a number above 0 and up to %2</source>
        <translation>l&apos;épaisseur %1 n&apos;est pas un nombre supérieur à 0 et inférieur ou égal à %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="90"/>
        <source>the pose table</source>
        <translation>la table des poses</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="97"/>
        <source>a pose</source>
        <translation>une pose</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="24"/>
        <source>the skeleton</source>
        <translation>le squelette</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="27"/>
        <source>its skeleton has no joints</source>
        <translation>son squelette n&apos;a aucune articulation</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="34"/>
        <source>skeleton joint %1 has a non-finite value</source>
        <translation>l&apos;articulation %1 du squelette a une valeur non finie</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="41"/>
        <source>skeleton joint %1 has a negative radius</source>
        <translation>l&apos;articulation %1 du squelette a un rayon négatif</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="45"/>
        <source>skeleton joint %1 has an invalid parent</source>
        <translation>l&apos;articulation %1 du squelette a un parent invalide</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="50"/>
        <source>the skeleton&apos;s root is not a root joint</source>
        <translation>la racine du squelette n&apos;est pas une articulation racine</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="51"/>
        <source>the skeleton&apos;s pose has a non-finite value</source>
        <translation>la pose du squelette a une valeur non finie</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="54"/>
        <source>a skeleton setting is outside 0 to 1</source>
        <translation>un réglage du squelette n&apos;est pas compris entre 0 et 1</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="64"/>
        <source>the skeleton has an unknown skinning mode</source>
        <translation>le squelette a un mode d&apos;habillage inconnu</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="73"/>
        <source>skeleton joint %1 has an unknown lock state</source>
        <translation>l’articulation %1 du squelette a un état de verrouillage inconnu</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="84"/>
        <source>the skeleton&apos;s limb bases</source>
        <translation>les bases des membres du squelette</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="87"/>
        <source>limb bases come without a skeleton</source>
        <translation>des bases de membres sont présentes sans squelette</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="90"/>
        <source>the skeleton has %1 joints but %2 limb base flags</source>
        <translation>le squelette a %1 articulations mais %2 marques de base de membre</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="99"/>
        <source>skeleton joint %1 has an unknown limb base flag</source>
        <translation>l’articulation %1 du squelette a une marque de base de membre inconnue</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_recover.cpp" line="51"/>
        <source>%1 damaged bytes could not be read; reading goes on with section %2</source>
        <translation>%1 octets endommagés n&apos;ont pas pu être lus&#xa0;; la lecture reprend à la section %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_recover.cpp" line="59"/>
        <source>the last %1 bytes of the file are damaged and could not be read</source>
        <translation>les %1 derniers octets du fichier sont endommagés et n&apos;ont pas pu être lus</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/finbook_file_recover.cpp" line="139"/>
        <source>%n missing or repeated id(s) were replaced by new ones</source>
        <translation>
            <numerusform>%n identifiant manquant ou en double a été remplacé par un nouveau</numerusform>
            <numerusform>%n identifiants manquants ou en double ont été remplacés par de nouveaux</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/recovery/autosaver.cpp" line="162"/>
        <source>Autosave could not write a recovery copy: %1.</source>
        <translation>L&apos;enregistrement automatique n&apos;a pas pu écrire de copie de récupération&#xa0;: %1.</translation>
    </message>
    <message>
        <location filename="../model/src/recovery/recovery_writer.h" line="43"/>
        <source>there is not enough memory</source>
        <translation>la mémoire est insuffisante</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="49"/>
        <source>the fill list</source>
        <translation>la liste des remplissages</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="52"/>
        <source>the object claims %1 fills, more than %2</source>
        <translation>l&apos;objet annonce %1 remplissages, plus que %2</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="42"/>
        <source>a fill&apos;s seed is not a number</source>
        <translation>le point de départ d&apos;un remplissage n&apos;est pas un nombre</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="27"/>
        <source>a fill names the stroke id %1, which no stroke can have</source>
        <translation>un remplissage désigne l’identifiant de trait %1, qu’aucun trait ne peut avoir</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="33"/>
        <source>a fill&apos;s stroke ids are not in order</source>
        <translation>les identifiants de traits d&apos;un remplissage ne sont pas dans l&apos;ordre</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="69"/>
        <source>the fill regions</source>
        <translation>les régions des remplissages</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="72"/>
        <source>the object gives regions of %1 fills but has %2</source>
        <translation>l’objet donne les régions de %1 remplissages mais en a %2</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="82"/>
        <source>the object&apos;s fills claim more than %1 regions</source>
        <translation>les remplissages de l’objet revendiquent plus de %1 régions</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="48"/>
        <location filename="../model/src/reference/reference_section.cpp" line="50"/>
        <source>the reference layer</source>
        <translation>le calque de référence</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="52"/>
        <source>the section is repeated</source>
        <translation>la section est répétée</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="57"/>
        <source>the reference is of an unknown kind (%1)</source>
        <translation>la référence est d’un type inconnu (%1)</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="61"/>
        <source>the reference has unknown flags</source>
        <translation>la référence a des indicateurs inconnus</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="76"/>
        <source>the reference&apos;s place, scale, rotation, opacity or rate is not a number or out of range</source>
        <translation>la position, l’échelle, la rotation, l’opacité ou la cadence de la référence n’est pas un nombre ou est hors limites</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="80"/>
        <source>the reference&apos;s name is too long</source>
        <translation>le nom de la référence est trop long</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="86"/>
        <source>the reference claims %1 bytes but only %2 remain</source>
        <translation>la référence annonce %1 octets mais il n’en reste que %2</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="99"/>
        <source>the reference layer is left out: %1</source>
        <translation>le calque de référence est laissé de côté : %1</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="106"/>
        <location filename="../model/src/reference/reference_section.cpp" line="108"/>
        <source>the reference&apos;s picture sequence</source>
        <translation>la séquence d’images de la référence</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="112"/>
        <source>it does not follow a reference picture, or is repeated</source>
        <translation>elle ne suit aucune image de référence, ou est répétée</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="115"/>
        <source>it claims %1 pictures</source>
        <translation>elle annonce %1 images</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="123"/>
        <source>picture %1 claims %2 bytes but only %3 remain</source>
        <translation>l’image %1 annonce %2 octets mais il n’en reste que %3</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="142"/>
        <source>the reference&apos;s further pictures are left out: %1</source>
        <translation>les images suivantes de la référence sont laissées de côté : %1</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="17"/>
        <source>sound clip %1</source>
        <translation>extrait sonore %1</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="20"/>
        <location filename="../model/src/sound/sound_section.cpp" line="34"/>
        <location filename="../model/src/sound/sound_section.cpp" line="79"/>
        <source>the sound clip</source>
        <translation>l&apos;extrait sonore</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="24"/>
        <source>%1; the sound clip is left out</source>
        <translation>%1 ; l&apos;extrait sonore est laissé de côté</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="32"/>
        <source>the file holds more than %1 sound clips</source>
        <translation>le fichier contient plus de %1 extraits sonores</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="39"/>
        <source>the sound starts at %1, outside 0 to %2</source>
        <translation>le son commence à %1, hors de 0 à %2</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="46"/>
        <source>the sound&apos;s volume %1 is outside 0 to %2</source>
        <translation>le volume %1 du son est hors de 0 à %2</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="54"/>
        <source>the sound flags 0x%1 are unknown</source>
        <translation>les indicateurs du son 0x%1 sont inconnus</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="58"/>
        <source>the sound&apos;s name is %1 bytes long (at most %2)</source>
        <translation>le nom du son fait %1 octets (au plus %2)</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="68"/>
        <source>the sound&apos;s name is not valid UTF-8 text</source>
        <translation>le nom du son n&apos;est pas un texte UTF-8 valide</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="72"/>
        <source>the sound is %1 MB long (at most %2 MB)</source>
        <translation>le son fait %1 Mo (au plus %2 Mo)</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="76"/>
        <source>the sound clip holds no sound</source>
        <translation>l&apos;extrait sonore ne contient aucun son</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_chunk.cpp" line="11"/>
        <source>the fill shading list</source>
        <translation>la liste des ombrages de remplissage</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_chunk.cpp" line="15"/>
        <source>the object shades %1 fills but has %2</source>
        <translation>l’objet ombre %1 remplissages mais en a %2</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_chunk.cpp" line="22"/>
        <source>a fill&apos;s shading (%1, %2) is not one Finbook knows</source>
        <translation>l’ombrage d’un remplissage (%1, %2) est inconnu de Finbook</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_chunk.cpp" line="34"/>
        <source>the light</source>
        <translation>la lumière</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_chunk.cpp" line="40"/>
        <source>the light&apos;s direction (%1°, %2°) is outside 0 to 360° and 0 to 90°</source>
        <translation>la direction de la lumière (%1°, %2°) sort de 0 à 360° et de 0 à 90°</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_section.cpp" line="13"/>
        <location filename="../model/src/camera/camera_section.cpp" line="15"/>
        <source>the camera</source>
        <translation>la caméra</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_section.cpp" line="20"/>
        <source>the camera has %1 keys (at most %2)</source>
        <translation>la caméra a %1 clés (au plus %2)</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_section.cpp" line="40"/>
        <source>camera key %1 holds a value out of range; it is left out</source>
        <translation>la clé de caméra %1 contient une valeur hors limites ; elle est laissée de côté</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_section.cpp" line="46"/>
        <source>camera key %1 is not after the key before it; it is left out</source>
        <translation>la clé de caméra %1 ne vient pas après la clé précédente ; elle est laissée de côté</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_section.cpp" line="59"/>
        <source>%1; the camera is left out</source>
        <translation>%1 ; la caméra est laissée de côté</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="14"/>
        <location filename="../model/src/scene/layer_section.cpp" line="16"/>
        <source>the layers</source>
        <translation>les calques</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="20"/>
        <source>the file has %1 layers (1 to %2)</source>
        <translation>le fichier a %1 calques (de 1 à %2)</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="28"/>
        <source>the layer</source>
        <translation>le calque</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="39"/>
        <source>its opacity is not between 0 and 1</source>
        <translation>son opacité n’est pas entre 0 et 1</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="44"/>
        <source>its depth is not between %1 and %2</source>
        <translation>sa profondeur n’est pas entre %1 et %2</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="59"/>
        <source>the layers hold %1 frames, but the file has %2</source>
        <translation>les calques contiennent %1 images, mais le fichier en a %2</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="76"/>
        <source>%1; every frame is put on one layer</source>
        <translation>%1 ; toutes les images sont mises sur un seul calque</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="14"/>
        <location filename="../model/src/swap/swap_section.cpp" line="16"/>
        <location filename="../model/src/swap/swap_section.cpp" line="52"/>
        <source>the swap sets</source>
        <translation>les jeux de dessins</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="21"/>
        <source>the file has %1 swap sets (at most %2)</source>
        <translation>le fichier a %1 jeux de dessins (au plus %2)</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="28"/>
        <source>swap set %1</source>
        <translation>jeu de dessins %1</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="33"/>
        <source>swap set %1 has %2 drawings (1 to %3)</source>
        <translation>le jeu de dessins %1 a %2 dessins (de 1 à %3)</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="44"/>
        <source>a drawing of swap set %1 carries a pose</source>
        <translation>un dessin du jeu %1 porte une pose</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="65"/>
        <source>object %1 shows a drawing the swap sets do not hold</source>
        <translation>l&apos;objet %1 montre un dessin absent des jeux de dessins</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="83"/>
        <source>the swap sets link objects the frames do not hold</source>
        <translation>les jeux de dessins lient des objets absents des images</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="95"/>
        <source>a frame shows a swap set on two objects</source>
        <translation>une image montre un jeu de dessins sur deux objets</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="113"/>
        <source>%1; the swap sets are left out</source>
        <translation>%1 ; les jeux de dessins sont laissés de côté</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="106"/>
        <location filename="../model/src/picture/picture_section.cpp" line="107"/>
        <location filename="../model/src/picture/picture_section.cpp" line="251"/>
        <source>the pictures</source>
        <translation>les images</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="118"/>
        <source>picture %1 is cut off</source>
        <translation>l’image %1 est tronquée</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="124"/>
        <source>picture %1&apos;s mesh has %2 vertices</source>
        <translation>le maillage de l’image %1 a %2 sommets</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="133"/>
        <source>picture %1&apos;s mesh has a vertex outside the picture</source>
        <translation>le maillage de l’image %1 a un sommet hors de l’image</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="140"/>
        <source>picture %1&apos;s mesh has no triangles</source>
        <translation>le maillage de l’image %1 n’a pas de triangle</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="148"/>
        <source>picture %1&apos;s mesh names a vertex it does not have</source>
        <translation>le maillage de l’image %1 désigne un sommet qu’il n’a pas</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="157"/>
        <source>picture %1&apos;s mesh has a triangle turned over or without area</source>
        <translation>le maillage de l’image %1 a un triangle retourné ou sans aire</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="167"/>
        <source>picture %1 is %2 × %3 pixels: %4</source>
        <translation>l’image %1 fait %2 × %3 pixels : %4</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="181"/>
        <location filename="../model/src/picture/picture_section.cpp" line="191"/>
        <source>picture %1 does not decode: %2</source>
        <translation>l’image %1 ne se décode pas : %2</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="196"/>
        <source>picture %1 is %2 × %3 pixels, not the %4 × %5 it claims</source>
        <translation>l’image %1 fait %2 × %3 pixels, et non les %4 × %5 annoncés</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="208"/>
        <source>%1; the objects showing it are left without it</source>
        <translation>%1 ; les objets qui la montrent restent sans elle</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="220"/>
        <source>the object&apos;s picture</source>
        <translation>l’image de l’objet</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="228"/>
        <source>the picture&apos;s place is out of range</source>
        <translation>la position de l’image est hors limites</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="236"/>
        <source>the picture&apos;s pose has a point out of range</source>
        <translation>la pose de l’image a un point hors limites</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="259"/>
        <source>an object shows picture %1, which the file does not hold</source>
        <translation>un objet montre l’image %1, que le fichier ne contient pas</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="284"/>
        <source>a picture&apos;s pose does not fit its mesh; it is shown at rest</source>
        <translation>la pose d’une image ne correspond pas à son maillage ; elle est montrée au repos</translation>
    </message>
</context>
<context>
    <name>MeshImport</name>
    <message>
        <location filename="../model/src/import/mesh_import.cpp" line="22"/>
        <source>Cannot import &quot;%1&quot;: %2</source>
        <translation>Impossible d&apos;importer «&#xa0;%1&#xa0;»&#xa0;: %2</translation>
    </message>
    <message>
        <location filename="../model/src/import/mesh_import.cpp" line="27"/>
        <source>Cannot import &quot;%1&quot;: the mesh has no boundary to draw.</source>
        <translation>Impossible d&apos;importer «&#xa0;%1&#xa0;»&#xa0;: le maillage n&apos;a pas de contour à dessiner.</translation>
    </message>
</context>
<context>
    <name>ObjectListModel</name>
    <message numerus="yes">
        <location filename="../model/src/object_list_model.cpp" line="170"/>
        <source>%1: %n stroke(s)</source>
        <translation>
            <numerusform>%1&#xa0;: %n trait</numerusform>
            <numerusform>%1&#xa0;: %n traits</numerusform>
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
        <translation>Noir</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="48"/>
        <source>Grey</source>
        <translation>Gris</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="49"/>
        <source>White</source>
        <translation>Blanc</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="49"/>
        <source>Purple</source>
        <translation>Violet</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="50"/>
        <source>Blue</source>
        <translation>Bleu</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="50"/>
        <source>Red</source>
        <translation>Rouge</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="51"/>
        <source>Orange</source>
        <translation>Orange</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="51"/>
        <source>Yellow</source>
        <translation>Jaune</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="52"/>
        <source>Green</source>
        <translation>Vert</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="52"/>
        <source>Brown</source>
        <translation>Marron</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="75"/>
        <source>it is not a GIMP palette (its first line is not &quot;GIMP Palette&quot;)</source>
        <translation>ce n&apos;est pas une palette GIMP (sa première ligne n&apos;est pas « GIMP Palette »)</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="97"/>
        <source>line %1: channels &quot;%2&quot; are not RGB or RGBA</source>
        <translation>ligne %1 : les canaux « %2 » ne sont ni RGB ni RGBA</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="117"/>
        <source>line %1 is not a colour (%2 numbers from 0 to 255, then a name)</source>
        <translation>la ligne %1 n&apos;est pas une couleur (%2 nombres de 0 à 255, puis un nom)</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="124"/>
        <source>it holds more than %1 colours</source>
        <translation>elle contient plus de %1 couleurs</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="176"/>
        <source>the palette is damaged</source>
        <translation>la palette est endommagée</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="182"/>
        <source>the palette claims %1 colours</source>
        <translation>la palette annonce %1 couleurs</translation>
    </message>
</context>
<context>
    <name>PictureImport</name>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="126"/>
        <source>Its stack.xml does not describe an OpenRaster image.</source>
        <translation>Son stack.xml ne décrit pas une image OpenRaster.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="136"/>
        <source>Its stack.xml gives a layer an invalid position or opacity.</source>
        <translation>Son stack.xml donne à un calque une position ou une opacité invalide.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="142"/>
        <source>Its layer groups are nested too deeply.</source>
        <translation>Ses groupes de calques sont imbriqués trop profondément.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="148"/>
        <source>Its stack.xml names a layer without a picture.</source>
        <translation>Son stack.xml nomme un calque sans image.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="152"/>
        <source>It has more than %1 layers.</source>
        <translation>Il a plus de %1 calques.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="159"/>
        <source>Its stack.xml is malformed (line %1: %2).</source>
        <translation>Son stack.xml est mal formé (ligne %1 : %2).</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="164"/>
        <source>Its stack.xml is empty.</source>
        <translation>Son stack.xml est vide.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="167"/>
        <source>Its stack of layers is empty.</source>
        <translation>Sa pile de calques est vide.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="177"/>
        <source>The picture of its layer “%1” (%2) is missing.</source>
        <translation>L’image de son calque « %1 » (%2) manque.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="182"/>
        <source>The picture of its layer “%1” is larger than %2 MB.</source>
        <translation>L’image de son calque « %1 » dépasse %2 Mo.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="187"/>
        <source>The picture of its layer “%1” is damaged or cut short in the file.</source>
        <translation>L’image de son calque « %1 » est endommagée ou tronquée dans le fichier.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="196"/>
        <source>Its layer “%1”: %2</source>
        <translation>Son calque « %1 » : %2</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="216"/>
        <source>It is a zip archive, but not an OpenRaster picture.</source>
        <translation>C’est une archive zip, mais pas une image OpenRaster.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="237"/>
        <source>It is not a zip archive, or it is damaged or cut short.</source>
        <translation>Ce n’est pas une archive zip, ou elle est endommagée ou tronquée.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="244"/>
        <source>It has no stack.xml: it is not an OpenRaster picture.</source>
        <translation>Elle n’a pas de stack.xml : ce n’est pas une image OpenRaster.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="248"/>
        <source>Its stack.xml is larger than %1 MB.</source>
        <translation>Son stack.xml dépasse %1 Mo.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="252"/>
        <source>Its stack.xml is damaged or cut short.</source>
        <translation>Son stack.xml est endommagé ou tronqué.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="272"/>
        <source>It has no visible layer.</source>
        <translation>Elle n’a aucun calque visible.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="23"/>
        <source>“%1” cannot be imported: %2</source>
        <translation>« %1 » ne peut pas être importé : %2</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="30"/>
        <source>Its picture has no size.</source>
        <translation>Son image n’a pas de taille.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="32"/>
        <source>It claims to be %1 × %2 pixels; a picture may be at most %3 pixels wide and high.</source>
        <translation>Elle annonce %1 × %2 pixels ; une image peut mesurer au plus %3 pixels de large et de haut.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="40"/>
        <source>It claims to be %1 × %2 pixels; a picture may have at most %3 megapixels.</source>
        <translation>Elle annonce %1 × %2 pixels ; une image peut avoir au plus %3 mégapixels.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="47"/>
        <source>Its pictures together would take more than %1 MB of memory.</source>
        <translation>Ses images prendraient ensemble plus de %1 Mo de mémoire.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="72"/>
        <source>Its picture is cut short (the file is incomplete).</source>
        <translation>Son image est tronquée (le fichier est incomplet).</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="83"/>
        <source>Its picture cannot be decoded: the file is damaged, cut short or too large.</source>
        <translation>Son image ne peut pas être décodée : le fichier est endommagé, tronqué ou trop grand.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="94"/>
        <location filename="../model/src/picture/picture_import.cpp" line="36"/>
        <source>It is empty.</source>
        <translation>Il est vide.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="102"/>
        <source>It holds a picture of a kind Finbook cannot read.</source>
        <translation>Il contient une image d’un type que Finbook ne sait pas lire.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="111"/>
        <source>Its picture cannot be decoded.</source>
        <translation>Son image ne peut pas être décodée.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="118"/>
        <source>There is not enough memory to read it.</source>
        <translation>Il n’y a pas assez de mémoire pour le lire.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_import.cpp" line="33"/>
        <source>It cannot be read (is it there, and may Finbook read it?).</source>
        <translation>Il ne peut pas être lu (existe-t-il, et Finbook a-t-il le droit de le lire ?).</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_import.cpp" line="45"/>
        <location filename="../model/src/picture/picture_import.cpp" line="49"/>
        <source>It is larger than %1 MB.</source>
        <translation>Il dépasse %1 Mo.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="44"/>
        <source>The picture is empty.</source>
        <translation>L’image est vide.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="49"/>
        <location filename="../model/src/picture/picture_object.cpp" line="275"/>
        <source>There is not enough memory for the picture.</source>
        <translation>Il n’y a pas assez de mémoire pour l’image.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="55"/>
        <source>The picture could not be encoded to be saved: %1</source>
        <translation>L’image n’a pas pu être encodée pour être enregistrée : %1</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="71"/>
        <source>The picture&apos;s outline cannot be traced: %1</source>
        <translation>Le contour de l’image ne peut pas être tracé : %1</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="75"/>
        <source>The picture is fully transparent: nothing of it shows.</source>
        <translation>L’image est entièrement transparente : rien n’en paraît.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="87"/>
        <source>The picture&apos;s outline cannot be meshed: %1</source>
        <translation>Le contour de l’image ne peut pas être maillé : %1</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="288"/>
        <source>The object has no picture.</source>
        <translation>L’objet n’a pas d’image.</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="268"/>
        <source>The posed picture is too large to keep (at most %1 pixels wide and high).</source>
        <translation>L’image posée est trop grande pour être gardée (au plus %1 pixels de large et de haut).</translation>
    </message>
</context>
<context>
    <name>QCommandLineParser</name>
    <message>
        <location filename="../app/main.cpp" line="26"/>
        <source>Displays help on commandline options.</source>
        <translation>Afficher l&apos;aide sur les options de la ligne de commande.</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="27"/>
        <source>Displays help including Qt specific options.</source>
        <translation>Afficher l&apos;aide, y compris les options propres à Qt.</translation>
    </message>
</context>
<context>
    <name>Reference</name>
    <message>
        <location filename="../model/src/reference/reference_commands.cpp" line="16"/>
        <source>Import Reference</source>
        <translation>Importer une référence</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_commands.cpp" line="18"/>
        <source>Reference Opacity</source>
        <translation>Opacité de la référence</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_commands.cpp" line="20"/>
        <source>Show or Hide Reference</source>
        <translation>Afficher ou masquer la référence</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_commands.cpp" line="22"/>
        <source>Lock or Unlock Reference</source>
        <translation>Verrouiller ou déverrouiller la référence</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/tool_reference.cpp" line="26"/>
        <location filename="../model/src/reference/reference_commands.cpp" line="24"/>
        <source>Move Reference</source>
        <translation>Déplacer la référence</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/tool_reference.cpp" line="22"/>
        <location filename="../model/src/reference/reference_commands.cpp" line="26"/>
        <source>Scale Reference</source>
        <translation>Mettre la référence à l’échelle</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/tool_reference.cpp" line="24"/>
        <location filename="../model/src/reference/reference_commands.cpp" line="28"/>
        <source>Rotate Reference</source>
        <translation>Faire pivoter la référence</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_commands.cpp" line="30"/>
        <source>Reference Frame Rate</source>
        <translation>Cadence de la référence</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_commands.cpp" line="91"/>
        <source>Remove Reference</source>
        <translation>Retirer la référence</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_import.cpp" line="34"/>
        <source>“%1” cannot be used as a reference: %2</source>
        <translation>« %1 » ne peut pas servir de référence : %2</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_import.cpp" line="44"/>
        <source>It cannot be read (is it there, and may Finbook read it?).</source>
        <translation>Il ne peut pas être lu (existe-t-il, et Finbook a-t-il le droit de le lire ?).</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_import.cpp" line="67"/>
        <source>It is larger than %1 MB.</source>
        <translation>Il dépasse %1 Mo.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_import.cpp" line="53"/>
        <source>It is empty.</source>
        <translation>Il est vide.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_media.cpp" line="111"/>
        <location filename="../model/src/reference/reference_media.cpp" line="135"/>
        <source>The file is empty.</source>
        <translation>Le fichier est vide.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_media.cpp" line="69"/>
        <source>Its picture cannot be decoded.</source>
        <translation>Son image ne peut pas être décodée.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="85"/>
        <source>Its SVG declares entities, which Finbook does not expand.</source>
        <translation>Son SVG déclare des entités, que Finbook ne développe pas.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="113"/>
        <location filename="../model/src/reference/reference_svg.cpp" line="215"/>
        <source>It is not a valid SVG picture.</source>
        <translation>Ce n’est pas une image SVG valide.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="152"/>
        <source>Its SVG uses an element inside itself (a loop of &lt;use&gt;).</source>
        <translation>Son SVG utilise un élément à l’intérieur de lui-même (une boucle de &lt;use&gt;).</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="210"/>
        <source>SVG pictures are drawn only where Finbook runs with its graphical application (their text needs its fonts).</source>
        <translation>Les images SVG ne sont dessinées que là où Finbook tourne avec son application graphique (leur texte a besoin de ses polices).</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="185"/>
        <source>The reference&apos;s SVG pictures took all the time Finbook spends drawing them.</source>
        <translation>Les images SVG de la référence ont pris tout le temps que Finbook consacre à les dessiner.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="193"/>
        <source>Its compressed SVG is damaged or larger than 16 MB.</source>
        <translation>Son SVG compressé est endommagé ou dépasse 16 Mo.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="197"/>
        <source>Its SVG is larger than 16 MB.</source>
        <translation>Son SVG dépasse 16 Mo.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="204"/>
        <source>Its SVG paints more than 100,000 elements (counting what &lt;use&gt; repeats), more than Finbook draws for a reference.</source>
        <translation>Son SVG dessine plus de 100 000 éléments (en comptant ce que &lt;use&gt; répète), plus que Finbook n’en dessine pour une référence.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="221"/>
        <source>Its SVG has no size.</source>
        <translation>Son SVG n’a pas de taille.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="228"/>
        <location filename="../model/src/reference/video_decoder.cpp" line="184"/>
        <location filename="../model/src/reference/video_decoder.cpp" line="189"/>
        <location filename="../model/src/reference/video_decoder.cpp" line="193"/>
        <location filename="../model/src/reference/video_decoder.cpp" line="221"/>
        <source>There is not enough memory to read it.</source>
        <translation>Il n’y a pas assez de mémoire pour la lire.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="257"/>
        <source>Its SVG takes too long to draw (more than %1 s), more than Finbook spends on a reference.</source>
        <translation>Son SVG est trop long à dessiner (plus de %1 s), plus que Finbook n’y consacre pour une référence.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/video_decoder.cpp" line="197"/>
        <location filename="../model/src/reference/video_decoder.cpp" line="201"/>
        <source>It is not a picture or a video Finbook can read, or it is damaged.</source>
        <translation>Ce n’est pas une image ou une vidéo que Finbook sait lire, ou elle est endommagée.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/video_decoder.cpp" line="204"/>
        <source>It is damaged: its streams cannot be read.</source>
        <translation>Elle est endommagée : ses flux ne peuvent pas être lus.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/video_decoder.cpp" line="208"/>
        <source>It holds no picture Finbook can decode.</source>
        <translation>Elle ne contient aucune image que Finbook sait décoder.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/video_decoder.cpp" line="213"/>
        <source>Its pictures are empty or larger than 16384 pixels a side.</source>
        <translation>Ses images sont vides ou font plus de 16384 pixels de côté.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/video_decoder.cpp" line="231"/>
        <source>Its pictures cannot be decoded.</source>
        <translation>Ses images ne peuvent pas être décodées.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/video_decoder.cpp" line="238"/>
        <source>Its first picture cannot be decoded.</source>
        <translation>Sa première image ne peut pas être décodée.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_sequence.cpp" line="75"/>
        <source>No picture was chosen.</source>
        <translation>Aucune image n’a été choisie.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_sequence.cpp" line="78"/>
        <source>A sequence of more than %1 pictures cannot be used as a reference.</source>
        <translation>Une séquence de plus de %1 images ne peut pas servir de référence.</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_sequence.cpp" line="87"/>
        <source>The pictures together are larger than %1 MB.</source>
        <translation>Les images dépassent ensemble %1 Mo.</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/reference/reference_sequence.cpp" line="108"/>
        <source>%1 and %n more</source>
        <extracomment>%1 is the first file&apos;s name, %n how many pictures follow it</extracomment>
        <translation>
            <numerusform>%1 et %n autre</numerusform>
            <numerusform>%1 et %n autres</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RigPrompt</name>
    <message>
        <location filename="../ui/src/rig/rig_prompt.cpp" line="20"/>
        <source>&quot;%1&quot; is posed. Removing its rig sends the drawing back to rest. (Apply Pose to Drawing first keeps the pose.)</source>
        <translation>« %1 » est en pose. Supprimer son rig ramène le dessin au repos. (Appliquer d’abord la pose au dessin garde la pose.)</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/rig_prompt.cpp" line="24"/>
        <source>Discard the Pose?</source>
        <translation>Abandonner la pose&#xa0;?</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/rig_prompt.cpp" line="22"/>
        <source>&quot;%1&quot; is posed. Replacing its rig sends the drawing back to rest. (Apply Pose to Drawing first keeps the pose.)</source>
        <translation>«&#xa0;%1&#xa0;» est posé. Remplacer son armature ramène le dessin au repos. (Utilisez d&apos;abord «&#xa0;Appliquer la pose au dessin&#xa0;» pour conserver la pose.)</translation>
    </message>
</context>
<context>
    <name>Sound</name>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="90"/>
        <source>The file is not a sound Finbook can read (WAV, FLAC, MP3, Ogg, Opus, AAC or M4A), or it is damaged.</source>
        <translation>Le fichier n&apos;est pas un son que Finbook sait lire (WAV, FLAC, MP3, Ogg, Opus, AAC ou M4A), ou il est endommagé.</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="211"/>
        <source>It holds more sound than a file of %1 KB can hold when it is real sound (more than %2 min; hostile or damaged files announce hours of sound in a few kilobytes). Convert it to WAV, FLAC or MP3 and import it again.</source>
        <translation>Il contient plus de son qu’un fichier de %1 Ko ne peut en contenir quand c’est du vrai son (plus de %2 min ; des fichiers malveillants ou endommagés annoncent des heures de son en quelques kilo-octets). Convertissez-le en WAV, FLAC ou MP3 et importez-le à nouveau.</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="240"/>
        <source>With the soundtrack&apos;s other clips it would make more than %1 min of sound, the most Finbook decodes from sound files of this size.</source>
        <translation>Avec les autres clips de la bande son, cela ferait plus de %1 min de son, le maximum que Finbook décode à partir de fichiers sonores de cette taille.</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="251"/>
        <source>The file is empty.</source>
        <translation>Le fichier est vide.</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="253"/>
        <source>The file is incomplete: its sound data is cut off. Import the complete file.</source>
        <translation>Le fichier est incomplet : ses données sonores sont tronquées. Importez le fichier complet.</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="261"/>
        <location filename="../model/src/sound/sound_decode.cpp" line="265"/>
        <location filename="../model/src/sound/sound_decode.cpp" line="269"/>
        <location filename="../model/src/sound/sound_decode.cpp" line="305"/>
        <source>There is not enough memory to read the sound.</source>
        <translation>La mémoire est insuffisante pour lire le son.</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="279"/>
        <source>The file holds no sound Finbook can play.</source>
        <translation>Le fichier ne contient aucun son que Finbook sait lire.</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="197"/>
        <source>Its sample rate, %1 Hz, is outside the %2 to %3 Hz Finbook plays (real recordings use 8,000 to 192,000).</source>
        <translation>Sa fréquence d’échantillonnage, %1 Hz, est hors de la plage de %2 à %3 Hz que Finbook lit (les vrais enregistrements utilisent 8 000 à 192 000).</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="294"/>
        <source>It has %1 channels; Finbook plays at most %2.</source>
        <translation>Il a %1 canaux ; Finbook en lit au plus %2.</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="353"/>
        <source>The sound is longer than %1 minutes, the longest Finbook plays.</source>
        <translation>Le son dure plus de %1 minutes, la plus longue durée que Finbook lit.</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="362"/>
        <source>The file holds no sound Finbook can play (no audio could be decoded from it).</source>
        <translation>Le fichier ne contient aucun son que Finbook sait lire (aucun son n&apos;a pu en être décodé).</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="369"/>
        <source>The file is incomplete: it announces %1 s of sound but holds only %2 s. Import the complete file.</source>
        <translation>Le fichier est incomplet : il annonce %1 s de son mais n’en contient que %2 s. Importez le fichier complet.</translation>
    </message>
</context>
<context>
    <name>StrokeEditing</name>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="124"/>
        <source>There is no frame to draw on. Insert a frame first.</source>
        <translation>Il n&apos;y a aucune image sur laquelle dessiner. Insérez d&apos;abord une image.</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="127"/>
        <source>The object &quot;%1&quot; is locked. Unlock it in the Objects panel to draw on it.</source>
        <translation>L&apos;objet «&#xa0;%1&#xa0;» est verrouillé. Déverrouillez-le dans le panneau Objets pour dessiner dessus.</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="130"/>
        <source>The object &quot;%1&quot; is hidden. Show it in the Objects panel to draw on it.</source>
        <translation>L&apos;objet «&#xa0;%1&#xa0;» est masqué. Affichez-le dans le panneau Objets pour dessiner dessus.</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="152"/>
        <source>Object</source>
        <translation>Objet</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="191"/>
        <source>%1 (pose applied)</source>
        <translation>%1 (pose appliquée)</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="288"/>
        <source>Delete Strokes</source>
        <translation>Supprimer les traits</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="288"/>
        <source>Delete Picture</source>
        <translation>Supprimer l’image</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="410"/>
        <source>Cut</source>
        <translation>Couper</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="486"/>
        <source>The clipboard holds strokes this version of Finbook cannot read.</source>
        <translation>Le presse-papiers contient des traits que cette version de Finbook ne sait pas lire.</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="496"/>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="497"/>
        <source>Paste</source>
        <translation>Coller</translation>
    </message>
</context>
<context>
    <name>Thumbnail</name>
    <message>
        <location filename="../app/thumbnail/first_frame.cpp" line="54"/>
        <source>it is not a regular file</source>
        <translation>ce n&apos;est pas un fichier ordinaire</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/first_frame.cpp" line="393"/>
        <source>Cannot make a thumbnail of &quot;%1&quot;: %2</source>
        <translation>Impossible de créer une vignette de «&#xa0;%1&#xa0;»&#xa0;: %2</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/first_frame.cpp" line="442"/>
        <source>a checksum does not match, so the file is damaged.</source>
        <translation>une somme de contrôle ne correspond pas, le fichier est donc endommagé.</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/first_frame.cpp" line="444"/>
        <source>it holds data that this version of Finbook does not know.</source>
        <translation>il contient des données que cette version de Finbook ne connaît pas.</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/first_frame.cpp" line="447"/>
        <source>the file is damaged or incomplete.</source>
        <translation>le fichier est endommagé ou incomplet.</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/thumbnail_command.cpp" line="138"/>
        <source>Usage: finbook thumbnail FILE OUT.png SIZE</source>
        <translation>Utilisation&#xa0;: finbook thumbnail FICHIER SORTIE.png TAILLE</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/thumbnail_command.cpp" line="144"/>
        <source>The thumbnail size &quot;%1&quot; is not a whole number from 1 to %2.</source>
        <translation>La taille de vignette «&#xa0;%1&#xa0;» n&apos;est pas un nombre entier de 1 à %2.</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/thumbnail_command.cpp" line="153"/>
        <source>Cannot make a thumbnail of &quot;%1&quot;: it has no frame.</source>
        <translation>Impossible de créer une vignette de «&#xa0;%1&#xa0;»&#xa0;: il n&apos;a aucune image.</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/thumbnail_command.cpp" line="163"/>
        <source>Cannot make a thumbnail of &quot;%1&quot;: there is not enough memory.</source>
        <translation>Impossible de créer une vignette de «&#xa0;%1&#xa0;»&#xa0;: la mémoire est insuffisante.</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/thumbnail_command.cpp" line="169"/>
        <source>Cannot write the thumbnail &quot;%1&quot;: %2.</source>
        <translation>Impossible d&apos;écrire la vignette «&#xa0;%1&#xa0;»&#xa0;: %2.</translation>
    </message>
</context>
<context>
    <name>finbook::model::FrameListModel</name>
    <message numerus="yes">
        <location filename="../model/src/frame_list_model.cpp" line="151"/>
        <source>Frame %1, held for %n frame(s)</source>
        <translation>
            <numerusform>Image %1, exposée pendant %n image</numerusform>
            <numerusform>Image %1, exposée pendant %n images</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/frame_list_model.cpp" line="152"/>
        <source>Frame %1</source>
        <translation>Image %1</translation>
    </message>
</context>
<context>
    <name>finbook::model::lipsync</name>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="31"/>
        <source>The file holds no mouth shapes.</source>
        <translation>Le fichier ne contient aucune forme de bouche.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="44"/>
        <source>The file is larger than %1 MiB, too large for lip sync timings.</source>
        <translation>Le fichier dépasse %1 Mio, trop pour des temps de synchro labiale.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="55"/>
        <source>The file is empty.</source>
        <translation>Le fichier est vide.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="149"/>
        <source>Line %1: &quot;%2&quot; is not a time from 0 to %3 seconds.</source>
        <translation>Ligne %1 : « %2 » n&apos;est pas un temps de 0 à %3 secondes.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="158"/>
        <source>Line %1: the time goes backwards.</source>
        <translation>Ligne %1 : le temps recule.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="165"/>
        <source>Line %1: the mouth cue ends before it starts.</source>
        <translation>Ligne %1 : la forme de bouche finit avant de commencer.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="172"/>
        <source>The file holds more than %1 mouth cues.</source>
        <translation>Le fichier contient plus de %1 formes de bouche.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="179"/>
        <source>Line %1: &quot;%2&quot; is not a mouth shape.</source>
        <translation>Ligne %1 : « %2 » n&apos;est pas une forme de bouche.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="213"/>
        <source>The frame rate %1 is not a number above 0 and up to %2.</source>
        <translation>La cadence %1 n&apos;est pas un nombre supérieur à 0 et au plus %2.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="221"/>
        <source>The file ends too early, after line %1.</source>
        <translation>Le fichier s&apos;arrête trop tôt, après la ligne %1.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="228"/>
        <source>Line %1: &quot;%2&quot; is not a whole number from %3 to %4.</source>
        <translation>Ligne %1 : « %2 » n&apos;est pas un entier de %3 à %4.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="256"/>
        <source>The Papagayo file holds no phonemes.</source>
        <translation>Le fichier Papagayo ne contient aucun phonème.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="299"/>
        <source>Line 1: a Papagayo file starts with &quot;lipsync version 1&quot;.</source>
        <translation>Ligne 1 : un fichier Papagayo commence par « lipsync version 1 ».</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="309"/>
        <source>Line %1: the frame rate &quot;%2&quot; is not a number above 0 and up to %3.</source>
        <translation>Ligne %1 : la cadence « %2 » n&apos;est pas un nombre supérieur à 0 et au plus %3.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="354"/>
        <source>Line %1 is not a word (&quot;text, start frame, end frame, phoneme count&quot;).</source>
        <translation>La ligne %1 n&apos;est pas un mot (« texte, image de début, image de fin, nombre de phonèmes »).</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="380"/>
        <source>Line %1 is not a phoneme (&quot;frame name&quot;).</source>
        <translation>La ligne %1 n&apos;est pas un phonème (« image nom »).</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="388"/>
        <source>Line %1: the phoneme at frame %2 comes after its word&apos;s end, frame %3.</source>
        <translation>Ligne %1 : le phonème de l&apos;image %2 vient après la fin de son mot, image %3.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="438"/>
        <source>The XML is damaged at line %1: %2.</source>
        <translation>Le XML est endommagé à la ligne %1 : %2.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="478"/>
        <source>Mouth cue %1: its &quot;%2&quot; is not a time from 0 to %3 seconds.</source>
        <translation>Forme de bouche %1 : son « %2 » n&apos;est pas un temps de 0 à %3 secondes.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="501"/>
        <source>Mouth cue %1 ends before it starts.</source>
        <translation>La forme de bouche %1 finit avant de commencer.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="508"/>
        <source>Mouth cue %1: its &quot;value&quot; &quot;%2&quot; is not a mouth shape.</source>
        <translation>Forme de bouche %1 : sa « value » « %2 » n&apos;est pas une forme de bouche.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="514"/>
        <source>Mouth cue %1: the time goes backwards.</source>
        <translation>Forme de bouche %1 : le temps recule.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="537"/>
        <source>The JSON is damaged at character %1: %2.</source>
        <translation>Le JSON est endommagé au caractère %1 : %2.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="543"/>
        <source>The JSON has no &quot;mouthCues&quot; list: it is not a Rhubarb Lip Sync result.</source>
        <translation>Le JSON n&apos;a pas de liste « mouthCues » : ce n&apos;est pas un résultat de Rhubarb Lip Sync.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="566"/>
        <source>Line %1: the XML&apos;s root is &lt;%2&gt;, not &lt;rhubarbResult&gt;: it is not a Rhubarb Lip Sync result.</source>
        <translation>Ligne %1 : la racine du XML est &lt;%2&gt;, pas &lt;rhubarbResult&gt; : ce n&apos;est pas un résultat de Rhubarb Lip Sync.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="601"/>
        <source>Line %1 is not &quot;seconds, tab, shape letter&quot;.</source>
        <translation>La ligne %1 n&apos;est pas « secondes, tabulation, lettre de forme ».</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="629"/>
        <source>Line %1: Moho switch data starts with &quot;MohoSwitch1&quot;.</source>
        <translation>Ligne %1 : les données switch de Moho commencent par « MohoSwitch1 ».</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="644"/>
        <source>Line %1 is not &quot;frame shape&quot;.</source>
        <translation>La ligne %1 n&apos;est pas « image forme ».</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="649"/>
        <source>Line %1: &quot;%2&quot; is not a frame number from 1 to %3.</source>
        <translation>Ligne %1 : « %2 » n&apos;est pas un numéro d&apos;image de 1 à %3.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="671"/>
        <source>Line %1: the letter &quot;%2&quot; is among Preston Blair&apos;s names; a file uses one naming or the other.</source>
        <translation>Ligne %1 : la lettre « %2 » est parmi les noms de Preston Blair ; un fichier emploie l&apos;une ou l&apos;autre façon de nommer.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="724"/>
        <source>&quot;%1&quot; could not be opened: %2.</source>
        <translation>« %1 » n&apos;a pas pu être ouvert : %2.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="746"/>
        <source>&quot;%1&quot; is not lip sync timings that Finbook reads: Papagayo (.pgo), Moho switch data (.dat) or Rhubarb Lip Sync (.tsv, .json, .xml).</source>
        <translation>« %1 » n&apos;est pas un fichier de synchro labiale que Finbook lit : Papagayo (.pgo), données switch de Moho (.dat) ou Rhubarb Lip Sync (.tsv, .json, .xml).</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="756"/>
        <source>Lip sync timings</source>
        <translation>Temps de synchro labiale</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="137"/>
        <source>The sound&apos;s sample rate (%1 Hz) is not one speech can be recognised at.</source>
        <translation>La fréquence d&apos;échantillonnage du son (%1 Hz) ne permet pas de reconnaître la parole.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="142"/>
        <source>The sound is too short to hold speech (less than a tenth of a second).</source>
        <translation>Le son est trop court pour contenir de la parole (moins d&apos;un dixième de seconde).</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="146"/>
        <source>The sound is damaged: some of its samples are not numbers.</source>
        <translation>Le son est endommagé : certains de ses échantillons ne sont pas des nombres.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="151"/>
        <source>The sound is silent: there is no speech to recognise. Check that the clip is the one with the dialogue and that it is not muted.</source>
        <translation>Le son est muet : il n&apos;y a pas de parole à reconnaître. Vérifiez que le clip est bien celui du dialogue et qu&apos;il n&apos;est pas coupé.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="173"/>
        <source>The speech models are not installed (looked in %1; on Debian and Ubuntu install the package pocketsphinx-en-us). Mouth shapes follow the loudness only.</source>
        <translation>Les modèles de parole ne sont pas installés (cherchés dans %1 ; sous Debian et Ubuntu, installez le paquet pocketsphinx-en-us). Les formes de bouche ne suivent que le volume.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="520"/>
        <source>The dialogue could not be prepared for recognition: %1</source>
        <translation>Le dialogue n&apos;a pas pu être préparé pour la reconnaissance : %1</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="529"/>
        <source>The speech models are damaged: %1</source>
        <translation>Les modèles de parole sont endommagés : %1</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="593"/>
        <source>Speech recognition failed: %1</source>
        <translation>La reconnaissance de la parole a échoué : %1</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="602"/>
        <source>Lip sync was canceled.</source>
        <translation>La synchro labiale a été annulée.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="854"/>
        <source>The speech models could not be loaded (%1). Mouth shapes follow the loudness only.</source>
        <translation>Les modèles de parole n&apos;ont pas pu être chargés (%1). Les formes de bouche ne suivent que le volume.</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="866"/>
        <source>The dialogue does not match the sound: the mouth follows the phones heard, without the dialogue.</source>
        <translation>Le dialogue ne correspond pas au son : la bouche suit les sons entendus, sans le dialogue.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::BetweenFitView</name>
    <message>
        <location filename="../ui/src/inbetween/between_fit_view.cpp" line="38"/>
        <source>Drag from a line of the first drawing to where it belongs on the second to pin it there; drag a pin to move it, right-click it to take it away.</source>
        <translation>Faites glisser d’une ligne du premier dessin jusqu’à sa place sur le second pour l’y épingler ; faites glisser une épingle pour la déplacer, clic droit pour la retirer.</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/between_fit_view.cpp" line="137"/>
        <source>No drawing to fit</source>
        <translation>Aucun dessin à ajuster</translation>
    </message>
</context>
<context>
    <name>finbook::ui::BezierEditorDialog</name>
    <message>
        <location filename="../ui/src/camera/bezier_editor.cpp" line="117"/>
        <source>Camera Easing Curve</source>
        <translation>Courbe d’accélération de la caméra</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/bezier_editor.cpp" line="124"/>
        <source>Ease</source>
        <translation>Douce</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/bezier_editor.cpp" line="125"/>
        <source>Ease In</source>
        <translation>Départ lent</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/bezier_editor.cpp" line="126"/>
        <source>Ease Out</source>
        <translation>Arrivée lente</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/bezier_editor.cpp" line="127"/>
        <source>Ease In and Out</source>
        <translation>Départ et arrivée lents</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/bezier_editor.cpp" line="128"/>
        <source>Overshoot</source>
        <translation>Dépassement</translation>
    </message>
</context>
<context>
    <name>finbook::ui::BoneTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/skeleton/tool_bone.h" line="40"/>
        <source>Bone</source>
        <translation>Os</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/skeleton/tool_bone.h" line="43"/>
        <source>build a skeleton and pose the drawing by its bones</source>
        <translation>construire un squelette et poser le dessin par ses os</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="55"/>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="168"/>
        <source>Build Skeleton</source>
        <translation>Construire le squelette</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="56"/>
        <source>The object is posed with another deformer. Building a skeleton discards that pose. Build it anyway?</source>
        <translation>L&apos;objet est posé avec un autre déformateur. Construire un squelette abandonne cette pose. Le construire quand même&#xa0;?</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="186"/>
        <source>Joined to %1. Shift-drag its root to join it elsewhere; right-click it to detach it.</source>
        <translation>Joint à %1. Faites glisser sa racine avec Maj pour le joindre ailleurs ; clic droit dessus pour le détacher.</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="261"/>
        <source>Click on a visible, unlocked drawing to give it a skeleton.</source>
        <translation>Cliquez sur un dessin visible et déverrouillé pour lui donner un squelette.</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="268"/>
        <source>Drag a joint to move it, click a bone to insert a joint; right-click a joint to delete it.</source>
        <translation>Faites glisser une articulation pour la déplacer, cliquez sur un os pour insérer une articulation ; clic droit sur une articulation pour la supprimer.</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="271"/>
        <source>Drag a bone to turn it, a joint to pull it, the root to move the object; press L over a joint to lock it; Shift-drag the root onto another part to join them.</source>
        <translation>Faites glisser un os pour le tourner, une articulation pour la tirer, la racine pour déplacer l’objet ; L sur une articulation la verrouille ; faites glisser la racine avec Maj sur une autre partie pour les joindre.</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="366"/>
        <source>Drop the root on a bone of another part to join them.</source>
        <translation>Déposez la racine sur un os d’une autre partie pour les joindre.</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="374"/>
        <source>%1 hangs from this part already, so it cannot hang from it in turn.</source>
        <translation>%1 est déjà suspendu à cette partie ; elle ne peut donc pas être suspendue à lui en retour.</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="115"/>
        <source>Edit Joints: drag a joint to move it, click a bone to insert a joint.</source>
        <translation>Modifier les articulations : faites glisser une articulation pour la déplacer, cliquez sur un os pour insérer une articulation.</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="130"/>
        <source>Reset the pose or apply it to the drawing before editing joints.</source>
        <translation>Réinitialisez la pose ou appliquez-la au dessin avant de modifier les articulations.</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="192"/>
        <source>Unlock Joint</source>
        <translation>Déverrouiller l’articulation</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="192"/>
        <source>Lock Joint</source>
        <translation>Verrouiller l’articulation</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="197"/>
        <source>Reset Bone Pose</source>
        <translation>Réinitialiser la pose de l’os</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="200"/>
        <source>Edit Joints</source>
        <translation>Modifier les articulations</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="205"/>
        <source>Insert Joint Here</source>
        <translation>Insérer une articulation ici</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="207"/>
        <source>Delete Joint</source>
        <translation>Supprimer l’articulation</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="211"/>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="263"/>
        <source>Make Root Joint</source>
        <translation>Faire l’articulation racine</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="220"/>
        <source>Detach from %1</source>
        <translation>Détacher de %1</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="223"/>
        <source>Make Character Root</source>
        <translation>Faire la racine du personnage</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="224"/>
        <source>Join Overlapping Parts</source>
        <translation>Joindre les parties qui se chevauchent</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="275"/>
        <source>No part overlaps another part&apos;s skeleton.</source>
        <translation>Aucune partie ne chevauche le squelette d’une autre partie.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="279"/>
        <source>Joined %n part(s).</source>
        <translation>
            <numerusform>%n partie jointe.</numerusform>
            <numerusform>%n parties jointes.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::ui::BrushToolBar</name>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="16"/>
        <source>Brush</source>
        <translation>Pinceau</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="23"/>
        <source>Pressure</source>
        <translation>Pression</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="37"/>
        <source>Width:</source>
        <translation>Épaisseur&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="42"/>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="44"/>
        <source>Smoothing:</source>
        <translation>Lissage&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="47"/>
        <source>How much a stroke is smoothed when the pen lifts</source>
        <translation>Force du lissage appliqué au trait quand le stylet se lève</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="49"/>
        <source>Stabiliser:</source>
        <translation>Stabilisateur :</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="52"/>
        <source>Off</source>
        <translation>Désactivé</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="53"/>
        <source>Steadies the line while you draw: the ink follows the pen on a string this long (4 screen pixels a step), so a shaky hand draws a smooth line. Off: the ink is under the pen.</source>
        <translation>Stabilise le trait pendant le dessin : l&apos;encre suit le stylet au bout d&apos;un fil de cette longueur (4 pixels d&apos;écran par cran), si bien qu&apos;une main tremblante trace une ligne lisse. Désactivé : l&apos;encre est sous le stylet.</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="58"/>
        <source>A tablet&apos;s pressure sets the line&apos;s width; off, every line has the full width</source>
        <translation>La pression de la tablette fixe la largeur du trait ; désactivée, chaque trait a toute sa largeur</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="116"/>
        <source>Pen colour %1</source>
        <translation>Couleur du stylo&#xa0;: %1</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="117"/>
        <source>Pen colour %1 (%2)</source>
        <translation>Couleur du stylo %1 (%2)</translation>
    </message>
</context>
<context>
    <name>finbook::ui::CageActions</name>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="33"/>
        <source>&amp;Fit Cage</source>
        <translation>Ajuster une &amp;cage</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="35"/>
        <source>Put a coarse cage around the current object in one step</source>
        <translation>Placer en une seule étape une cage grossière autour de l&apos;objet courant</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="36"/>
        <source>Shift+C</source>
        <translation>Shift+C</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="37"/>
        <source>Edit Cage &amp;Shape</source>
        <translation>Modifier la &amp;forme de la cage</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="41"/>
        <source>Change the cage itself (move, add or delete corners) instead of posing with it</source>
        <translation>Modifier la cage elle-même (déplacer, ajouter ou supprimer des coins) au lieu de poser avec elle</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="67"/>
        <source>Corners </source>
        <translation>Coins </translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="68"/>
        <source>About how many corners Fit Cage gives the cage</source>
        <translation>Nombre approximatif de coins que «&#xa0;Ajuster une cage&#xa0;» donne à la cage</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="82"/>
        <source>Choose an unlocked object with strokes to fit a cage to.</source>
        <translation>Choisissez un objet déverrouillé contenant des traits pour y ajuster une cage.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::CageTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/cage/tool_cage.h" line="23"/>
        <source>Cage</source>
        <translation>Cage</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/cage/tool_cage.h" line="26"/>
        <source>draw a cage around the drawing, then drag its corners to bend it</source>
        <translation>tracer une cage autour du dessin, puis tirer ses coins pour le plier</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/tool_cage.cpp" line="132"/>
        <source>Choose an object first: the cage goes around it.</source>
        <translation>Choisissez d&apos;abord un objet&#xa0;: la cage se place autour de lui.</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/tool_cage.cpp" line="258"/>
        <source>A cage needs at least three corners.</source>
        <translation>Une cage doit avoir au moins trois coins.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::CameraTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/camera/tool_camera.h" line="30"/>
        <source>Camera</source>
        <translation>Caméra</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/camera/tool_camera.h" line="33"/>
        <source>frame the shot: move, zoom and turn the camera</source>
        <translation>cadrer le plan : déplacer, zoomer et tourner la caméra</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="189"/>
        <source>Easing to the Next Key</source>
        <translation>Accélération jusqu’à la clé suivante</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="193"/>
        <source>Linear</source>
        <translation>Linéaire</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="194"/>
        <source>Ease In</source>
        <translation>Départ lent</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="195"/>
        <source>Ease Out</source>
        <translation>Arrivée lente</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="196"/>
        <source>Ease In and Out</source>
        <translation>Départ et arrivée lents</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="197"/>
        <source>Hold, Then Cut</source>
        <translation>Tenir, puis couper</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="208"/>
        <source>Bézier Curve...</source>
        <translation>Courbe de Bézier...</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="214"/>
        <source>Delete Camera Key</source>
        <translation>Supprimer la clé de caméra</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="217"/>
        <source>Reset Camera</source>
        <translation>Réinitialiser la caméra</translation>
    </message>
</context>
<context>
    <name>finbook::ui::CanvasWidget</name>
    <message>
        <location filename="../ui/src/canvas/canvas_widget.cpp" line="311"/>
        <source>The layer &quot;%1&quot; is locked: unlock it (Layer &gt; Lock Layer, or its padlock in the timeline) to draw on it.</source>
        <translation>Le calque « %1 » est verrouillé : déverrouillez-le (Calque &gt; Verrouiller le calque, ou son cadenas dans la timeline) pour dessiner dessus.</translation>
    </message>
    <message>
        <location filename="../ui/src/canvas/canvas_widget.cpp" line="314"/>
        <source>The layer &quot;%1&quot; is hidden: show it (Layer &gt; Show Layer, or its eye in the timeline) to draw on it.</source>
        <translation>Le calque « %1 » est masqué : affichez-le (Calque &gt; Afficher le calque, ou son œil dans la timeline) pour dessiner dessus.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ColorButton</name>
    <message>
        <location filename="../ui/src/widgets/color_button.cpp" line="13"/>
        <source>Choose a colour</source>
        <translation>Choisir une couleur</translation>
    </message>
    <message>
        <location filename="../ui/src/widgets/color_button.cpp" line="31"/>
        <source>Choose Colour</source>
        <translation>Choisir une couleur</translation>
    </message>
</context>
<context>
    <name>finbook::ui::DeformActions</name>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="26"/>
        <source>&amp;Reset Pose</source>
        <translation>&amp;Réinitialiser la pose</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="30"/>
        <source>&amp;Apply Pose to Drawing</source>
        <translation>&amp;Appliquer la pose au dessin</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="29"/>
        <source>Move the current object&apos;s pins, cage corners or bones back to their rest positions</source>
        <translation>Ramener les épingles, les coins de cage ou les os de l&apos;objet courant à leur position de repos</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="32"/>
        <source>Make the posed drawing the object&apos;s new strokes; the pins, cage or skeleton stay where they are</source>
        <translation>Faire du dessin posé les nouveaux traits de l&apos;objet&#xa0;; les épingles, la cage ou le squelette restent en place</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="34"/>
        <source>Remo&amp;ve Rig</source>
        <translation>Re&amp;tirer l&apos;armature</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="37"/>
        <source>Take the pins, the cage or the skeleton off the current object</source>
        <translation>Retirer les épingles, la cage ou le squelette de l&apos;objet courant</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="57"/>
        <source>The posed picture is now the object&apos;s picture: resampled once, it is a little softer. Undo brings back the original.</source>
        <translation>L’image posée est désormais l’image de l’objet : rééchantillonnée une fois, elle est un peu plus douce. Annuler rend l’original.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/rig/deform_actions.cpp" line="74"/>
        <source>The pins fold the drawing: %n triangle(s) of its mesh turned over where the pins leave no room (View → Show Mesh shows them red)</source>
        <translation>
            <numerusform>Les épingles plient le dessin&#xa0;: %n triangle de son maillage est retourné là où elles ne laissent pas de place (Affichage → Afficher le maillage le montre en rouge)</numerusform>
            <numerusform>Les épingles plient le dessin&#xa0;: %n triangles de son maillage sont retournés là où elles ne laissent pas de place (Affichage → Afficher le maillage les montre en rouge)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="79"/>
        <source>Preparing the deformation…</source>
        <translation>Préparation de la déformation…</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="89"/>
        <source>R&amp;igidity</source>
        <translation>R&amp;igidité</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="103"/>
        <source>Converged (Most Rigid)</source>
        <translation>Convergence (rigidité maximale)</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="104"/>
        <source>As in the Paper (Two Steps)</source>
        <translation>Comme dans l&apos;article (deux étapes)</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="105"/>
        <source>Stiffer (+1 Pass)</source>
        <translation>Plus rigide (+1 passe)</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="106"/>
        <source>Stiffest (+3 Passes)</source>
        <translation>Le plus rigide (+3 passes)</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="139"/>
        <source>Mesh density </source>
        <translation>Densité du maillage </translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="140"/>
        <source>How fine the current object&apos;s deformation mesh is (1 = default)</source>
        <translation>Finesse du maillage de déformation de l&apos;objet courant (1 = par défaut)</translation>
    </message>
</context>
<context>
    <name>finbook::ui::DocumentSettingsDialog</name>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="26"/>
        <source>Start again after the last frame</source>
        <translation>Recommencer après la dernière image</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="30"/>
        <source>Document Settings</source>
        <translation>Paramètres du document</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="32"/>
        <source> fps</source>
        <translation> i/s</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="35"/>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="40"/>
        <source>Last</source>
        <translation>Dernière</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="50"/>
        <source>to</source>
        <translation>à</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="54"/>
        <source>&amp;Frame rate:</source>
        <translation>&amp;Fréquence d&apos;images&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="55"/>
        <source>Canvas size:</source>
        <translation>Taille du canevas&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="56"/>
        <source>&amp;Background:</source>
        <translation>Arrière-&amp;plan&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="57"/>
        <source>Loop:</source>
        <translation>Boucle&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="58"/>
        <source>Play frames:</source>
        <translation>Images à lire&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="125"/>
        <source>Background Colour</source>
        <translation>Couleur d&apos;arrière-plan</translation>
    </message>
</context>
<context>
    <name>finbook::ui::EraserTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_eraser.h" line="29"/>
        <source>Eraser</source>
        <translation>Gomme</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_eraser.h" line="30"/>
        <source>rub out parts of lines, or whole strokes</source>
        <translation>gommer des parties de traits, ou des traits entiers</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_eraser.cpp" line="160"/>
        <source>Erase</source>
        <translation>Effacer</translation>
    </message>
</context>
<context>
    <name>finbook::ui::EraserToolBar</name>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="11"/>
        <source>Eraser</source>
        <translation>Gomme</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="13"/>
        <source>Cut Lines</source>
        <translation>Couper les traits</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="14"/>
        <source>Whole Strokes</source>
        <translation>Traits entiers</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="25"/>
        <source>Erase the part of a line under the eraser (the rest is split into pieces)</source>
        <translation>Efface la partie d’un trait sous la gomme (le reste est coupé en morceaux)</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="28"/>
        <source>Erase every stroke the eraser touches (or hold Shift when you start rubbing)</source>
        <translation>Efface chaque trait que touche la gomme (ou maintenez Maj en commençant à gommer)</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="31"/>
        <source>Size:</source>
        <translation>Taille&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="35"/>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="36"/>
        <source>The eraser&apos;s diameter on the canvas</source>
        <translation>Le diamètre de la gomme sur la toile</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ExportDialog</name>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="59"/>
        <location filename="../ui/src/export/export_dialog.cpp" line="340"/>
        <source>Export Animation</source>
        <translation>Exporter l&apos;animation</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="67"/>
        <location filename="../ui/src/export/export_dialog.cpp" line="328"/>
        <source>untitled</source>
        <translation>sans titre</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="79"/>
        <source>Animated GIF</source>
        <translation>GIF animé</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="80"/>
        <source>MP4 video (H.264)</source>
        <translation>Vidéo MP4 (H.264)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="81"/>
        <source>WebM video (VP9)</source>
        <translation>Vidéo WebM (VP9)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="82"/>
        <source>Animated PNG (APNG)</source>
        <translation>PNG animé (APNG)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="83"/>
        <source>HTML flipbook (one file)</source>
        <translation>Folioscope HTML (un seul fichier)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="84"/>
        <source>Lottie animation (JSON), for web pages and apps</source>
        <translation>Animation Lottie (JSON), pour pages web et applications</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="85"/>
        <source>dotLottie animation (compressed Lottie)</source>
        <translation>Animation dotLottie (Lottie compressé)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="86"/>
        <source>PNG images (a folder)</source>
        <translation>Images PNG (un dossier)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="87"/>
        <source>SVG vector images (a folder)</source>
        <translation>Images vectorielles SVG (un dossier)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="88"/>
        <source>3D model (OBJ), the current frame</source>
        <translation>Modèle 3D (OBJ), l&apos;image courante</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="89"/>
        <source>3D model (glTF binary), the current frame</source>
        <translation>Finbook, un éditeur d&apos;animation en folioscope.

  finbook [FILE]               ouvrir FILE dans l&apos;éditeur
  finbook info FILE            afficher un résumé JSON de FILE
  finbook export FILE OUTDIR   rendre chaque image dans OUTDIR/frame_0001.png ...
  finbook export FILE OUT      exporter vers OUT.gif, .mp4, .webm, .apng ou .html
  finbook export FILE OUT.obj --frame N   l&apos;image N en modèle 3D (OUT.obj, OUT.mtl)
  finbook export FILE OUT.glb --frame N   l&apos;image N en modèle 3D (glTF binaire)
  finbook export FILE... --format F --out-dir DIR   exporter plusieurs fichiers
  finbook thumbnail FILE OUT.png SIZE   écrire la première image en PNG d&apos;au plus SIZE px</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="93"/>
        <source>&amp;Browse...</source>
        <translation>Parc&amp;ourir...</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="95"/>
        <source>Play range</source>
        <translation>Plage de lecture</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="96"/>
        <source>All frames</source>
        <translation>Toutes les images</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="97"/>
        <source>Frames</source>
        <translation>Images</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="112"/>
        <source>Document background</source>
        <translation>Arrière-plan du document</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="113"/>
        <source>Transparent</source>
        <translation>Transparent</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="114"/>
        <source>Colour</source>
        <translation>Couleur</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="118"/>
        <source> fps</source>
        <translation> i/s</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="119"/>
        <source>Start again after the last frame</source>
        <translation>Recommencer après la dernière image</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="120"/>
        <source>One file per drawing, with an exposure sheet</source>
        <translation>Un fichier par dessin, avec une feuille d&apos;exposition</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="121"/>
        <source>Include refere&amp;nce</source>
        <translation>Inclure la référe&amp;nce</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="123"/>
        <source>Paint the reference picture or video under the drawing (not in SVG or 3D)</source>
        <translation>Peindre l’image ou la vidéo de référence sous le dessin (pas en SVG ni en 3D)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="143"/>
        <source>to</source>
        <translation>à</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="158"/>
        <source>&amp;Format:</source>
        <translation>&amp;Format&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="159"/>
        <source>&amp;Save to:</source>
        <translation>Enregistrer &amp;dans&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="160"/>
        <source>F&amp;rames:</source>
        <translation>&amp;Images&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="161"/>
        <source>Sc&amp;ale:</source>
        <translation>É&amp;chelle&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="162"/>
        <source>&amp;Background:</source>
        <translation>Arrière-&amp;plan&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="163"/>
        <source>Frame ra&amp;te:</source>
        <translation>Fré&amp;quence d&apos;images&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="164"/>
        <source>Loop:</source>
        <translation>Boucle&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="169"/>
        <source>&amp;Export</source>
        <translation>&amp;Exporter</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="170"/>
        <source>Cancel Export</source>
        <translation>Annuler l&apos;export</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="271"/>
        <source>%1 x %2 pixels</source>
        <translation>%1 x %2 pixels</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="274"/>
        <source>A 3D model holds the current frame (%1) only: its objects inflated, in their fill colours, with a .mtl file beside it. The frames, scale, background and frame rate do not apply.</source>
        <translation>Un modèle 3D ne contient que l&apos;image courante (%1) : ses objets gonflés, dans leurs couleurs de remplissage, avec un fichier .mtl à côté. Les images, l&apos;échelle, le fond et la cadence ne s&apos;appliquent pas.</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="279"/>
        <source>A 3D model holds the current frame (%1) only: its objects inflated, in their fill colours, all in one file. The frames, scale, background and frame rate do not apply.</source>
        <translation>Un modèle 3D ne contient que l&apos;image courante (%1) : ses objets gonflés, dans leurs couleurs de remplissage, le tout dans un seul fichier. Les images, l&apos;échelle, le fond et la cadence ne s&apos;appliquent pas.</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="284"/>
        <source>This format needs the ffmpeg program, which was not found; install it (on Debian: apt install ffmpeg) first.</source>
        <translation>Ce format nécessite le programme ffmpeg, qui est introuvable&#xa0;; installez-le d&apos;abord (sous Debian&#xa0;: apt install ffmpeg).</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="289"/>
        <source>The video carries the soundtrack, trimmed to the frames exported.</source>
        <translation>La vidéo porte la bande son, coupée aux images exportées.</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="291"/>
        <source>The page carries the soundtrack; it plays with the frames once the viewer presses Play.</source>
        <translation>La page porte la bande son ; elle joue avec les images dès que le spectateur appuie sur Lecture.</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="293"/>
        <source>This format has no sound: the soundtrack is left out (MP4, WebM and HTML carry it).</source>
        <translation>Ce format n&apos;a pas de son : la bande son est laissée de côté (MP4, WebM et HTML la portent).</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="337"/>
        <source>Export to Folder</source>
        <translation>Exporter dans un dossier</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="341"/>
        <source>%1 files (*.%2)</source>
        <translation>Fichiers %1 (*.%2)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="30"/>
        <source>Choose where to export the animation to.</source>
        <translation>Choisissez où exporter l&apos;animation.</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="56"/>
        <source>Exporting...</source>
        <translation>Exportation...</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="68"/>
        <source>Cancelling...</source>
        <translation>Annulation...</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/export/export_dialog_run.cpp" line="86"/>
        <source>Exported %n file(s) to %1</source>
        <translation>
            <numerusform>%n fichier exporté dans %1</numerusform>
            <numerusform>%n fichiers exportés dans %1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="99"/>
        <source>Export cancelled; nothing was written.</source>
        <translation>Export annulé&#xa0;; rien n&apos;a été écrit.</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="124"/>
        <source>&quot;%1&quot; already exists. Replace it?</source>
        <translation>«&#xa0;%1&#xa0;» existe déjà. Le remplacer&#xa0;?</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/export/export_dialog_run.cpp" line="125"/>
        <source>%n file(s) at the target already exist, such as &quot;%1&quot;. Replace them?</source>
        <translation>
            <numerusform>%n fichier existe déjà à la destination&#xa0;: «&#xa0;%1&#xa0;». Le remplacer&#xa0;?</numerusform>
            <numerusform>%n fichiers existent déjà à la destination, par exemple «&#xa0;%1&#xa0;». Les remplacer&#xa0;?</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="128"/>
        <source>Replace Files?</source>
        <translation>Remplacer les fichiers&#xa0;?</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="135"/>
        <source>Export Anyway?</source>
        <translation>Exporter quand même ?</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="137"/>
        <source>It may take a long time and a lot of disk space. Export anyway?</source>
        <translation>Cela peut prendre longtemps et beaucoup d’espace disque. Exporter quand même ?</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="145"/>
        <source>Cannot Export</source>
        <translation>Impossible d&apos;exporter</translation>
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
        <translation>prendre la couleur d&apos;un trait ou d&apos;un remplissage pour le stylo</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_eyedropper.cpp" line="63"/>
        <source>Nothing here to take a colour from: click a line or a fill.</source>
        <translation>Aucune couleur à prélever ici : cliquez sur un trait ou un remplissage.</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_eyedropper.cpp" line="70"/>
        <source>The pen takes the line&apos;s colour %1.</source>
        <translation>Le stylo prend la couleur %1 du trait.</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_eyedropper.cpp" line="71"/>
        <source>The pen takes the fill&apos;s colour %1.</source>
        <translation>Le stylo prend la couleur %1 du remplissage.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::FillTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/fill/tool_fill.h" line="23"/>
        <source>Fill</source>
        <translation>Remplissage</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/fill/tool_fill.h" line="24"/>
        <source>fill an enclosed region with colour</source>
        <translation>remplir de couleur une région fermée</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/tool_fill.cpp" line="70"/>
        <source>No closed region here: close the outline, or raise Close gaps</source>
        <translation>Aucune zone fermée ici : fermez le contour ou augmentez « Fermer les trous »</translation>
    </message>
</context>
<context>
    <name>finbook::ui::FrameActions</name>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="13"/>
        <source>Insert Frame &amp;Before</source>
        <translation>Insérer une image ava&amp;nt</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="15"/>
        <source>&amp;Insert Frame After</source>
        <translation>&amp;Insérer une image après</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="17"/>
        <source>&amp;Duplicate Frame</source>
        <translation>&amp;Dupliquer l&apos;image</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="19"/>
        <source>Generate In-be&amp;tweens…</source>
        <translation>Générer des in&amp;tervalles…</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="21"/>
        <source>Delete Fra&amp;me</source>
        <translation>&amp;Supprimer l&apos;image</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="24"/>
        <source>Move Frame &amp;Left</source>
        <translation>Déplacer l&apos;image vers la &amp;gauche</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="26"/>
        <source>Move Frame &amp;Right</source>
        <translation>Déplacer l&apos;image vers la d&amp;roite</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="29"/>
        <source>Hold Lon&amp;ger</source>
        <translation>&amp;Allonger l&apos;exposition</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="31"/>
        <source>Hold &amp;Shorter</source>
        <translation>Ra&amp;ccourcir l&apos;exposition</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="34"/>
        <source>&amp;Previous Frame</source>
        <translation>Image &amp;précédente</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="37"/>
        <source>&amp;Next Frame</source>
        <translation>Image sui&amp;vante</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/timeline/frame_actions.cpp" line="126"/>
        <source>Delete %n Frame(s)</source>
        <translation>
            <numerusform>Supprimer %n image</numerusform>
            <numerusform>Supprimer %n images</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::ui::HandTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_hand.h" line="17"/>
        <source>Hand</source>
        <translation>Main</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_hand.h" line="18"/>
        <source>drag the view</source>
        <translation>faire glisser la vue</translation>
    </message>
</context>
<context>
    <name>finbook::ui::InbetweenDialog</name>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="63"/>
        <source>Generate In-betweens</source>
        <translation>Générer des intervalles</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="69"/>
        <source>Objects:</source>
        <translation>Objets&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="72"/>
        <source>Where the first drawing lands on the second (drag to pin):</source>
        <translation>Où le premier dessin arrive sur le second (glisser pour épingler) :</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="199"/>
        <source>With these pins the drawings could not be fitted: %1</source>
        <translation>Avec ces épingles, les dessins n’ont pas pu être ajustés : %1</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="246"/>
        <source>&amp;Frames between the keys:</source>
        <translation>&amp;Images entre les clés&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="249"/>
        <source>Linear</source>
        <translation>Linéaire</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="250"/>
        <source>Ease in (slow from the first key)</source>
        <translation>Démarrage progressif (lent depuis la première clé)</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="251"/>
        <source>Ease out (slow into the second key)</source>
        <translation>Arrêt progressif (lent en arrivant à la seconde clé)</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="252"/>
        <source>Ease in and out</source>
        <translation>Démarrage et arrêt progressifs</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="253"/>
        <source>Favour…</source>
        <translation>Favoriser…</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="254"/>
        <source>&amp;Spacing:</source>
        <translation>&amp;Espacement&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="258"/>
        <source>Left favours the first key, right the second.</source>
        <translation>À gauche, la première clé est favorisée&#xa0;; à droite, la seconde.</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="259"/>
        <source>F&amp;avour:</source>
        <translation>Fa&amp;voriser&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="262"/>
        <source>Move pins and cage corners along &amp;arcs</source>
        <translation>Déplacer les épingles et les coins de cage en &amp;arcs</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="265"/>
        <source>A limb swung between the keys keeps its length. Unchecked, every target moves in a straight line.</source>
        <translation>Un membre qui pivote entre les clés garde sa longueur. Si la case est décochée, chaque cible se déplace en ligne droite.</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="268"/>
        <source>Carry &amp;different drawings onto each other</source>
        <translation>Transporter les &amp;dessins différents l’un sur l’autre</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="272"/>
        <source>Where the two keys are separate drawings of an object, the first is fitted onto the second as rigidly as possible and carried there, fading into the second&apos;s lines at the end. Unchecked, the drawing switches over half way.</source>
        <translation>Là où les deux clés sont des dessins distincts d’un objet, le premier est ajusté sur le second aussi rigidement que possible et transporté jusqu’à lui, en se fondant à la fin dans ses lignes. Décoché, le dessin change à mi-chemin.</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="424"/>
        <source>Making the in-betweens…</source>
        <translation>Création des intervalles…</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="138"/>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="303"/>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="344"/>
        <source>(unnamed)</source>
        <translation>(sans nom)</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="39"/>
        <source>Move Correspondence Pins</source>
        <translation>Déplacer les épingles de correspondance</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="306"/>
        <source>%1: interpolated</source>
        <translation>%1&#xa0;: interpolé</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="308"/>
        <source>%1: held from the first key (no pins, cage or skeleton)</source>
        <translation>%1&#xa0;: maintenu depuis la première clé (ni épingles, ni cage, ni squelette)</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="310"/>
        <source>%1: held from the first key (its pins, cage or skeleton differ between the keys)</source>
        <translation>%1&#xa0;: maintenu depuis la première clé (ses épingles, sa cage ou son squelette diffèrent entre les clés)</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="314"/>
        <source>%1: only in the first key, held in the first half</source>
        <translation>%1&#xa0;: seulement dans la première clé, maintenu pendant la première moitié</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="316"/>
        <source>%1: only in the second key, held in the second half</source>
        <translation>%1&#xa0;: seulement dans la seconde clé, maintenu pendant la seconde moitié</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="318"/>
        <source>%1: carried from the first key&apos;s drawing to the second&apos;s</source>
        <translation>%1 : transporté du dessin de la première clé à celui de la seconde</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="328"/>
        <source>Select two different frames as keys.</source>
        <translation>Sélectionnez deux images différentes comme clés.</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="341"/>
        <source>%1: could not be carried onto the second key&apos;s drawing, so it switches over half way. %2</source>
        <translation>%1 : n’a pas pu être transporté sur le dessin de la seconde clé, il change donc à mi-chemin. %2</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="180"/>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="347"/>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="393"/>
        <source>Fitting the drawings that differ…</source>
        <translation>Ajustement des dessins différents…</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="348"/>
        <source>Posing the preview…</source>
        <translation>Calcul de l’aperçu…</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="389"/>
        <source>The preview could not be posed: %1</source>
        <translation>Impossible de poser l&apos;aperçu&#xa0;: %1</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="395"/>
        <source>No object has matching pins or a matching cage in both keys: the in-betweens will only hold drawings.</source>
        <translation>Aucun objet n&apos;a d&apos;épingles ou de cage correspondantes dans les deux clés&#xa0;: les intervalles ne feront que maintenir les dessins.</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="397"/>
        <source>The canvas shows the middle in-between.</source>
        <translation>Le canevas montre l&apos;intervalle du milieu.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::LayerActions</name>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="15"/>
        <source>Layer %1</source>
        <translation>Calque %1</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="32"/>
        <source>&amp;New Layer</source>
        <translation>&amp;Nouveau calque</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="39"/>
        <source>&amp;Duplicate Layer</source>
        <translation>&amp;Dupliquer le calque</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="46"/>
        <source>De&amp;lete Layer</source>
        <translation>&amp;Supprimer le calque</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="57"/>
        <source>Move Layer &amp;Up</source>
        <translation>&amp;Monter le calque</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="59"/>
        <source>Move Layer D&amp;own</source>
        <translation>D&amp;escendre le calque</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="66"/>
        <source>Layer &amp;Above</source>
        <translation>Calque a&amp;u-dessus</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="68"/>
        <source>Layer &amp;Below</source>
        <translation>Calque en-dess&amp;ous</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="71"/>
        <source>&amp;Show Layer</source>
        <translation>&amp;Afficher le calque</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="74"/>
        <source>Loc&amp;k Layer</source>
        <translation>&amp;Verrouiller le calque</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="77"/>
        <source>Layer &amp;Properties...</source>
        <translation>&amp;Propriétés du calque...</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="81"/>
        <source>&amp;Insert Time</source>
        <translation>&amp;Insérer du temps</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="83"/>
        <source>Delete &amp;Time</source>
        <translation>Supprimer du &amp;temps</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="121"/>
        <location filename="../ui/src/layers/layer_sheet.cpp" line="398"/>
        <source>Lock Layer</source>
        <translation>Verrouiller le calque</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="121"/>
        <location filename="../ui/src/layers/layer_sheet.cpp" line="398"/>
        <source>Unlock Layer</source>
        <translation>Déverrouiller le calque</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="122"/>
        <location filename="../ui/src/layers/layer_sheet.cpp" line="393"/>
        <source>Show Layer</source>
        <translation>Afficher le calque</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="122"/>
        <location filename="../ui/src/layers/layer_sheet.cpp" line="393"/>
        <source>Hide Layer</source>
        <translation>Masquer le calque</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="134"/>
        <source>Change Layer Properties</source>
        <translation>Modifier les propriétés du calque</translation>
    </message>
</context>
<context>
    <name>finbook::ui::LayerPropertiesDialog</name>
    <message>
        <location filename="../ui/src/layers/layer_properties_dialog.cpp" line="21"/>
        <source>Show its neighbouring drawings in the onion skin</source>
        <translation>Montrer ses dessins voisins en pelure d’oignon</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_properties_dialog.cpp" line="23"/>
        <source>Layer Properties</source>
        <translation>Propriétés du calque</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_properties_dialog.cpp" line="36"/>
        <source>How far behind the page the layer lies: at depth 1 the camera&apos;s pans and zooms move it half as much (a distant background), at 0 exactly as much, below 0 more (a foreground rushing past).</source>
        <translation>À quelle distance derrière la page se trouve le calque : à la profondeur 1, les panoramiques et zooms de la caméra le déplacent deux fois moins (un arrière-plan lointain), à 0 exactement autant, en dessous de 0 davantage (un premier plan qui défile).</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_properties_dialog.cpp" line="42"/>
        <source>&amp;Name:</source>
        <translation>&amp;Nom :</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_properties_dialog.cpp" line="43"/>
        <source>&amp;Opacity:</source>
        <translation>&amp;Opacité :</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_properties_dialog.cpp" line="44"/>
        <source>&amp;Depth:</source>
        <translation>&amp;Profondeur :</translation>
    </message>
</context>
<context>
    <name>finbook::ui::LipSyncDialog</name>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="67"/>
        <source>&amp;Run</source>
        <translation>&amp;Lancer</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="68"/>
        <source>&amp;Import Timings...</source>
        <translation>&amp;Importer des temps…</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="73"/>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="241"/>
        <source>Lip Sync</source>
        <translation>Synchro labiale</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="76"/>
        <source>Optional: the words spoken, for a closer fit</source>
        <translation>Facultatif : les mots prononcés, pour un calage plus juste</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="93"/>
        <source>%1 (from frame %2)</source>
        <translation>%1 (dès l&apos;image %2)</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="97"/>
        <source>Recognises English speech (PocketSphinx, US English). Other languages: import timings made elsewhere.</source>
        <translation>Reconnaît la parole anglaise (PocketSphinx, anglais américain). Autres langues : importez des temps faits ailleurs.</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="99"/>
        <source>The speech models are not installed (Debian: pocketsphinx-en-us): the mouth follows the loudness only, closed, half open or open.</source>
        <translation>Les modèles de parole ne sont pas installés (Debian : pocketsphinx-en-us) : la bouche ne suit que le volume, fermée, entrouverte ou ouverte.</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="103"/>
        <source>Mouth:</source>
        <translation>Bouche :</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="104"/>
        <source>%1 (%2 drawings)</source>
        <translation>%1 (%2 dessins)</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="105"/>
        <source>(none)</source>
        <translation>(aucune)</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="107"/>
        <source>&amp;Sound:</source>
        <translation>&amp;Son :</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="108"/>
        <source>&amp;Dialogue:</source>
        <translation>&amp;Dialogue :</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="120"/>
        <source>The animation has no sound: File &gt; Import Sound… first, or import timings made elsewhere.</source>
        <translation>L&apos;animation n&apos;a pas de son : d&apos;abord Fichier &gt; Importer un son…, ou importez des temps faits ailleurs.</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="125"/>
        <source>Import Lip Sync Timings</source>
        <translation>Importer des temps de synchro labiale</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="175"/>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="175"/>
        <source>Close</source>
        <translation>Fermer</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="193"/>
        <source>Listening…</source>
        <translation>Écoute…</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="211"/>
        <source>Cancelling…</source>
        <translation>Annulation…</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="217"/>
        <source>Cancelled: nothing was changed.</source>
        <translation>Annulé : rien n&apos;a été modifié.</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="221"/>
        <source>Nothing was changed.</source>
        <translation>Rien n&apos;a été modifié.</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="224"/>
        <source>from the loudness (the speech models are not installed)</source>
        <translation>d&apos;après le volume (les modèles de parole ne sont pas installés)</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="225"/>
        <source>from the recognised speech</source>
        <translation>d&apos;après la parole reconnue</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="226"/>
        <source>from the speech and the dialogue</source>
        <translation>d&apos;après la parole et le dialogue</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="228"/>
        <source>spelt by rules, not found in the dictionary: %1</source>
        <translation>épelés par règles, absents du dictionnaire : %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="246"/>
        <source>Keyed the mouth on %n frame(s), %1.</source>
        <translation>
            <numerusform>Bouche posée sur %n image, %1.</numerusform>
            <numerusform>Bouche posée sur %n images, %1.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="248"/>
        <source>%n frame(s) of the mouth&apos;s layer hold no mouth and were left as they were.</source>
        <translation>
            <numerusform>%n image du calque de la bouche n&apos;a pas de bouche et est restée telle quelle.</numerusform>
            <numerusform>%n images du calque de la bouche n&apos;ont pas de bouche et sont restées telles quelles.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="262"/>
        <source>%1 was not imported: %2</source>
        <translation>%1 n&apos;a pas été importé : %2</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="268"/>
        <source>from %1</source>
        <translation>d&apos;après %1</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="316"/>
        <source>The clip holds no sound to follow.</source>
        <translation>Le clip ne contient aucun son à suivre.</translation>
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
        <translation>%1 : %2</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="218"/>
        <source>Show Dr&amp;awing</source>
        <translation>&amp;Afficher le dessin</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="236"/>
        <source>Timeline</source>
        <translation>Chronologie</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="239"/>
        <source>Objects</source>
        <translation>Objets</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="243"/>
        <source>Reference</source>
        <translation>Référence</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="263"/>
        <source>&lt;opened document&gt;</source>
        <translation>&lt;document ouvert&gt;</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="265"/>
        <source>Undo History</source>
        <translation>Historique</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="272"/>
        <source>Palette</source>
        <translation>Palette</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="298"/>
        <source>Rotation </source>
        <translation>Rotation </translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="302"/>
        <source>The view&apos;s rotation: the drawing is not changed. Shift+Space-drag on the canvas turns it freely; 4 and 6 turn it by 15°, 5 resets it, Shift+M mirrors it.</source>
        <translation>La rotation de la vue : le dessin ne change pas. Maj+Espace et glisser sur la toile la tourne librement ; 4 et 6 la tournent de 15°, 5 la remet droite, Maj+M la retourne.</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="328"/>
        <source>The reference &quot;%1&quot; cannot be shown: %2</source>
        <translation>La référence « %1 » ne peut pas être affichée : %2</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="337"/>
        <source>%1, %2 px</source>
        <translation>%1, %2 px</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="348"/>
        <source>Frame %1 / %2</source>
        <translation>Image %1 / %2</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="349"/>
        <source>%1 %</source>
        <translation>%1&#xa0;%</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="354"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="436"/>
        <source>Untitled</source>
        <translation>Sans titre</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="355"/>
        <source>%1[*] - Finbook</source>
        <translation>%1[*] – Finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_deform.cpp" line="36"/>
        <source>&amp;Deform</source>
        <translation>Défor&amp;mer</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_deform.cpp" line="51"/>
        <source>&amp;Lip Sync...</source>
        <translation>Synchro &amp;labiale…</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_deform.cpp" line="52"/>
        <source>Key a mouth chart&apos;s drawings from the soundtrack</source>
        <translation>Poser les dessins d&apos;une planche de bouches d&apos;après la bande son</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_deform.cpp" line="74"/>
        <source>Preparing the deformation…</source>
        <translation>Préparation de la déformation…</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="38"/>
        <source>Finbook animations (*.finbook);;All files (*)</source>
        <translation>Animations Finbook (*.finbook);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="49"/>
        <source>Object</source>
        <translation>Objet</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="84"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="139"/>
        <source>Cannot Open File</source>
        <translation>Impossible d&apos;ouvrir le fichier</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="174"/>
        <source>Cannot Save File</source>
        <translation>Impossible d&apos;enregistrer le fichier</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="180"/>
        <source>Saved %1</source>
        <translation>%1 enregistré</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/window/main_window_files.cpp" line="146"/>
        <source>Opened what was readable of %1 (%n problem(s) repaired); save it under a new name.</source>
        <translation>
            <numerusform>Ce qui était lisible de %1 a été ouvert (%n problème réparé)&#xa0;; enregistrez l&apos;animation sous un nouveau nom.</numerusform>
            <numerusform>Ce qui était lisible de %1 a été ouvert (%n problèmes réparés)&#xa0;; enregistrez l&apos;animation sous un nouveau nom.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="102"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="107"/>
        <source>Cannot Open the Example</source>
        <translation>Impossible d&apos;ouvrir l&apos;exemple</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="112"/>
        <source>The example walk cycle: change it and save it as your own.</source>
        <translation>L&apos;exemple de cycle de marche : modifiez-le et enregistrez-le comme le vôtre.</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="230"/>
        <source>&amp;%1 %2</source>
        <translation>&amp;%1 %2</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="239"/>
        <source>No recent files</source>
        <translation>Aucun fichier récent</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="249"/>
        <source>Cannot Import Mesh</source>
        <translation>Impossible d&apos;importer le maillage</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="253"/>
        <location filename="../ui/src/window/main_window_menus.cpp" line="117"/>
        <source>Import Mesh</source>
        <translation>Importer un maillage</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="373"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="386"/>
        <source>Reading &quot;%1&quot;...</source>
        <translation>Lecture de « %1 »…</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="357"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="373"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="386"/>
        <location filename="../ui/src/window/main_window_menus.cpp" line="125"/>
        <source>Import Picture</source>
        <translation>Importer une image</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="337"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="375"/>
        <source>Cannot Import Picture</source>
        <translation>Impossible d’importer l’image</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="358"/>
        <source>&quot;%1&quot; stands on a flat background (%2). Make that colour transparent, so that the object is only what is drawn on it?</source>
        <translation>« %1 » repose sur un fond uni (%2). Rendre cette couleur transparente, pour que l’objet ne soit que ce qui est dessiné dessus ?</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/window/main_window_files.cpp" line="388"/>
        <source>Imported &quot;%1&quot;: %n picture object(s).</source>
        <translation>
            <numerusform>« %1 » importé : %n objet image.</numerusform>
            <numerusform>« %1 » importé : %n objets image.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="398"/>
        <source>Pasted picture</source>
        <translation>Image collée</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="410"/>
        <source>Reading the pasted picture...</source>
        <translation>Lecture de l’image collée...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="411"/>
        <source>Pasted a picture as an object.</source>
        <translation>Une image a été collée comme objet.</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="424"/>
        <source>Damaged File</source>
        <translation>Fichier endommagé</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="425"/>
        <source>Open anyway shows what is still readable as a new, unsaved animation; the damaged file is not changed.</source>
        <translation>«&#xa0;Ouvrir quand même&#xa0;» affiche ce qui reste lisible dans une nouvelle animation non enregistrée&#xa0;; le fichier endommagé n&apos;est pas modifié.</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="428"/>
        <source>Open Anyway</source>
        <translation>Ouvrir quand même</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="438"/>
        <source>Unsaved Changes</source>
        <translation>Modifications non enregistrées</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="439"/>
        <source>&quot;%1&quot; has changes that are not saved. Save them before going on?</source>
        <translation>«&#xa0;%1&#xa0;» contient des modifications non enregistrées. Les enregistrer avant de continuer&#xa0;?</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="445"/>
        <source>Open Animation</source>
        <translation>Ouvrir une animation</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="451"/>
        <source>Save Animation</source>
        <translation>Enregistrer l&apos;animation</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="452"/>
        <source>untitled.finbook</source>
        <translation>sans-titre.finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="65"/>
        <source>File</source>
        <translation>Fichier</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="77"/>
        <source>&amp;File</source>
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="78"/>
        <source>&amp;New</source>
        <translation>&amp;Nouveau</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="80"/>
        <source>&amp;Open...</source>
        <translation>&amp;Ouvrir...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="82"/>
        <source>Open Exa&amp;mple</source>
        <translation>Ouvrir l&apos;e&amp;xemple</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="84"/>
        <source>&amp;Welcome...</source>
        <translation>&amp;Bienvenue...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="91"/>
        <source>Open &amp;Recent</source>
        <translation>Fichiers &amp;récents</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="95"/>
        <source>&amp;Save</source>
        <translation>&amp;Enregistrer</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="97"/>
        <source>Save &amp;As...</source>
        <translation>Enregistrer &amp;sous...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="101"/>
        <source>E&amp;xport...</source>
        <translation>Ex&amp;porter...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="114"/>
        <source>&amp;Import Mesh...</source>
        <translation>&amp;Importer un maillage...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="117"/>
        <source>OFF meshes (*.off)</source>
        <translation>Maillages OFF (*.off)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="122"/>
        <source>Import &amp;Picture...</source>
        <translation>Importer une ima&amp;ge...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="126"/>
        <source>Pictures (*.png *.jpg *.jpeg *.webp *.tif *.tiff *.gif *.bmp *.ora);;OpenRaster stacks (*.ora);;All files (*)</source>
        <translation>Images (*.png *.jpg *.jpeg *.webp *.tif *.tiff *.gif *.bmp *.ora);;Piles OpenRaster (*.ora);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="132"/>
        <source>Import Re&amp;ference...</source>
        <translation>Importer une ré&amp;férence...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="138"/>
        <source>Cannot Import Reference</source>
        <translation>Impossible d’importer la référence</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="140"/>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="158"/>
        <source>&amp;Edit</source>
        <translation>É&amp;dition</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="160"/>
        <source>&amp;Undo</source>
        <translation>&amp;Annuler</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="164"/>
        <source>&amp;Redo</source>
        <translation>&amp;Rétablir</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="410"/>
        <location filename="../ui/src/window/main_window_menus.cpp" line="174"/>
        <source>Paste</source>
        <translation>Coller</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="179"/>
        <source>Cu&amp;t</source>
        <translation>Co&amp;uper</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="186"/>
        <source>&amp;Copy</source>
        <translation>&amp;Copier</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="193"/>
        <source>&amp;Paste</source>
        <translation>C&amp;oller</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="215"/>
        <source>&amp;Delete</source>
        <translation>&amp;Supprimer</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="222"/>
        <source>Select &amp;All</source>
        <translation>&amp;Tout sélectionner</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="228"/>
        <source>Dese&amp;lect</source>
        <translation>&amp;Désélectionner</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="235"/>
        <source>D&amp;ocument Settings...</source>
        <translation>Paramètres du docu&amp;ment...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="238"/>
        <source>Pre&amp;ferences...</source>
        <translation>&amp;Préférences...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="267"/>
        <source>&amp;View</source>
        <translation>&amp;Affichage</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="268"/>
        <source>Zoom &amp;In</source>
        <translation>Zoom &amp;avant</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="270"/>
        <source>Zoom &amp;Out</source>
        <translation>Zoom a&amp;rrière</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="272"/>
        <source>&amp;Fit to Window</source>
        <translation>Adapter à la &amp;fenêtre</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="274"/>
        <source>&amp;Actual Size (100 %)</source>
        <translation>&amp;Taille réelle (100&#xa0;%)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="280"/>
        <source>Rotate View &amp;Left</source>
        <translation>Tourner la vue à &amp;gauche</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="282"/>
        <source>Rotate View &amp;Right</source>
        <translation>Tourner la vue à &amp;droite</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="285"/>
        <source>R&amp;eset View Rotation</source>
        <translation>Ré&amp;initialiser la rotation de la vue</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="288"/>
        <source>Mirror Vie&amp;w</source>
        <translation>Vue en mir&amp;oir</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="296"/>
        <source>O&amp;nion Skin</source>
        <translation>&amp;Pelure d&apos;oignon</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="307"/>
        <source>Onion Skin &amp;Settings...</source>
        <translation>Réglages de la pe&amp;lure d&apos;oignon...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="309"/>
        <source>Show &amp;Mesh</source>
        <translation>Afficher le &amp;maillage</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="315"/>
        <source>&amp;Camera View</source>
        <translation>Vue &amp;caméra</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="321"/>
        <source>&amp;Dim Other Layers</source>
        <translation>Atténuer les a&amp;utres calques</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="328"/>
        <source>&amp;Panels</source>
        <translation>Pa&amp;nneaux</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="334"/>
        <source>F&amp;rame</source>
        <translation>&amp;Image</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="347"/>
        <source>&amp;Layer</source>
        <translation>&amp;Calque</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="354"/>
        <source>&amp;Object</source>
        <translation>&amp;Objet</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="372"/>
        <source>&amp;Tools</source>
        <translation>Ou&amp;tils</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="375"/>
        <source>Tools</source>
        <translation>Outils</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="383"/>
        <source>&amp;Help</source>
        <translation>Aid&amp;e</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="385"/>
        <source>Finbook &amp;Manual</source>
        <translation>&amp;Manuel de Finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="390"/>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>&amp;Raccourcis clavier</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="392"/>
        <source>&amp;About Finbook</source>
        <translation>À &amp;propos de Finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="422"/>
        <source>Onion Skin</source>
        <translation>Pelure d&apos;oignon</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="446"/>
        <source>About Finbook</source>
        <translation>À propos de Finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="447"/>
        <source>&lt;h3&gt;Finbook %1&lt;/h3&gt;&lt;p&gt;A flipbook animation editor: draw frame by frame, and bend drawings with pins.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Finbook %1&lt;/h3&gt;&lt;p&gt;Un éditeur d&apos;animation façon folioscope&#xa0;: dessinez image par image et déformez vos dessins avec des épingles.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="162"/>
        <location filename="../ui/src/window/main_window_toolbars.cpp" line="39"/>
        <source>Undo</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="166"/>
        <location filename="../ui/src/window/main_window_toolbars.cpp" line="41"/>
        <source>Redo</source>
        <translation>Rétablir</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_toolbars.cpp" line="45"/>
        <source>Apply Pose</source>
        <translation>Appliquer la pose</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_toolbars.cpp" line="47"/>
        <source>Remove Rig</source>
        <translation>Retirer l&apos;armature</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_toolbars.cpp" line="49"/>
        <source>Reset</source>
        <translation>Réinitialiser</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_toolbars.cpp" line="51"/>
        <source>Shape</source>
        <translation>Forme</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="30"/>
        <source>Reset &amp;Bone Pose</source>
        <translation>Réinitialiser la pose de l’&amp;os</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="31"/>
        <source>Turn the bone selected with the Bone tool back to rest; the bones below it keep their bends</source>
        <translation>Ramener au repos l’os choisi avec l’outil Os ; les os en dessous gardent leur flexion</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="35"/>
        <source>&amp;Edit Joints</source>
        <translation>&amp;Modifier les articulations</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="37"/>
        <source>With the Bone tool, move, insert and delete the joints of an unposed skeleton instead of posing it</source>
        <translation>Avec l’outil Os, déplacer, insérer et supprimer les articulations d’un squelette sans pose au lieu de le poser</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="58"/>
        <source>Show S&amp;keleton</source>
        <translation>Afficher le &amp;squelette</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="64"/>
        <source>Skeleton</source>
        <translation>Squelette</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="72"/>
        <source>S&amp;kinning</source>
        <translation>&amp;Habillage</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="79"/>
        <source>&amp;Rigid (Bones Pin the Mesh)</source>
        <translation>&amp;Rigide (les os épinglent le maillage)</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="81"/>
        <source>&amp;Linear Blend</source>
        <translation>Mélange &amp;linéaire</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="83"/>
        <source>&amp;Cut-out (Limbs Turn over the Body)</source>
        <translation>&amp;Découpage (les membres tournent par-dessus le corps)</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="115"/>
        <source>Rigid</source>
        <translation>Rigide</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="115"/>
        <source>Blend</source>
        <translation>Mélange</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="115"/>
        <source>Cut-out</source>
        <translation>Découpe</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/main_window_recovery.cpp" line="63"/>
        <source>Cannot Recover</source>
        <translation>Impossible de récupérer le travail</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/main_window_recovery.cpp" line="72"/>
        <source>Recovered %1 as it was at %2; save it to keep it.</source>
        <translation>%1 récupéré tel qu&apos;il était le %2&#xa0;; enregistrez-le pour le conserver.</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/close_gap_box.cpp" line="27"/>
        <location filename="../ui/src/fill/close_gap_box.cpp" line="35"/>
        <source>Close gaps: automatic</source>
        <translation>Fermer les trous : automatique</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/close_gap_box.cpp" line="34"/>
        <source>Close gaps: automatic (%1 px)</source>
        <translation>Fermer les trous : automatique (%1 px)</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="41"/>
        <source>Close gaps up to </source>
        <translation>Fermer les trous jusqu&apos;à </translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="42"/>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="43"/>
        <source>Openings in an outline up to this wide still make a region the Fill tool can fill (0 = only closed outlines)</source>
        <translation>Les ouvertures d&apos;un contour jusqu&apos;à cette largeur forment encore une zone que l&apos;outil Remplissage peut remplir (0 = contours fermés seulement)</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="88"/>
        <source>Fill All Enclosed Re&amp;gions</source>
        <translation>Remplir toutes les &amp;zones fermées</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="90"/>
        <source>Fill every closed region of the current object that has no fill, in the pen colour</source>
        <translation>Remplir de la couleur du stylo chaque zone fermée de l&apos;objet courant qui n&apos;a pas de remplissage</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="97"/>
        <source>The current object has no unfilled closed region</source>
        <translation>L&apos;objet courant n&apos;a aucune zone fermée sans remplissage</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="109"/>
        <source>The colour the Fill tool fills with (the pen&apos;s)</source>
        <translation>La couleur dont l&apos;outil Remplissage remplit (celle du stylo)</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/main_window_shade.cpp" line="33"/>
        <source>Shading</source>
        <translation>Ombrage</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/main_window_lipsync.cpp" line="15"/>
        <source>Lip Sync</source>
        <translation>Synchro labiale</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/main_window_lipsync.cpp" line="16"/>
        <source>Lip sync keys the drawings of a mouth chart. Make one with Object &gt; New Mouth Chart, redraw its mouths in your style, then come back here.</source>
        <translation>La synchro labiale pose les dessins d&apos;une planche de bouches. Créez-en une avec Objet &gt; Nouvelle planche de bouches, redessinez ses bouches à votre façon, puis revenez ici.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ManualBrowser</name>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="30"/>
        <location filename="../ui/src/help/manual_browser.cpp" line="99"/>
        <source>Contents</source>
        <translation>Sommaire</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="31"/>
        <source>Getting Started: Draw, Bend, Play</source>
        <translation>Premiers pas : dessiner, plier, jouer</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="32"/>
        <source>Drawing and the View</source>
        <translation>Dessiner et la vue</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="33"/>
        <source>Fills and Shading</source>
        <translation>Remplissages et ombrage</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="34"/>
        <source>Pins</source>
        <translation>Épingles</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="35"/>
        <source>Cages</source>
        <translation>Cages</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="36"/>
        <source>Bones and Skeletons</source>
        <translation>Os et squelettes</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="37"/>
        <source>In-betweens</source>
        <translation>Intervalles</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="38"/>
        <source>Timeline, Layers and Sound</source>
        <translation>Timeline, calques et son</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="39"/>
        <source>Swapping Drawings and Lip Sync</source>
        <translation>Dessins interchangeables et synchro labiale</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="40"/>
        <source>Camera</source>
        <translation>Caméra</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="41"/>
        <source>Pictures as Objects</source>
        <translation>Les images comme objets</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="42"/>
        <source>Reference Pictures and Video</source>
        <translation>Images et vidéos de référence</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="43"/>
        <source>Exporting</source>
        <translation>Exporter</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="44"/>
        <source>Saving, Autosave and Recovery</source>
        <translation>Enregistrement, sauvegarde automatique et récupération</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="45"/>
        <source>The Command Line</source>
        <translation>La ligne de commande</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="46"/>
        <source>Keyboard Shortcuts</source>
        <translation>Raccourcis clavier</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="47"/>
        <source>Installing</source>
        <translation>Installation</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="84"/>
        <source>Finbook Manual</source>
        <translation>Manuel de Finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="97"/>
        <source>Back</source>
        <translation>Précédent</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="98"/>
        <source>Forward</source>
        <translation>Suivant</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="104"/>
        <source>Search the manual</source>
        <translation>Chercher dans le manuel</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ObjectActions</name>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="28"/>
        <source>&amp;New Object</source>
        <translation>&amp;Nouvel objet</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="30"/>
        <source>&amp;Delete Object</source>
        <translation>&amp;Supprimer l&apos;objet</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="31"/>
        <source>&amp;Merge Objects</source>
        <translation>&amp;Fusionner les objets</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="34"/>
        <source>Move &amp;Selection to Object</source>
        <translation>&amp;Déplacer la sélection vers un objet</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="35"/>
        <source>Bring &amp;Forward</source>
        <translation>&amp;Monter</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="37"/>
        <source>Send &amp;Backward</source>
        <translation>D&amp;escendre</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="39"/>
        <source>&amp;Visible</source>
        <translation>&amp;Visible</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="40"/>
        <source>&amp;Locked</source>
        <translation>Ve&amp;rrouillé</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="43"/>
        <source>New object above the current one</source>
        <translation>Nouvel objet au-dessus de l&apos;objet courant</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="44"/>
        <source>Merge the selected objects, or the current one into the one below</source>
        <translation>Fusionner les objets sélectionnés, ou l&apos;objet courant avec celui du dessous</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="45"/>
        <source>Move the selected strokes to another object</source>
        <translation>Déplacer les traits sélectionnés vers un autre objet</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="47"/>
        <source>New</source>
        <translation>Nouveau</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="48"/>
        <source>Delete</source>
        <translation>Supprimer</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="49"/>
        <source>Merge</source>
        <translation>Fusionner</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="50"/>
        <source>Move To</source>
        <translation>Déplacer vers</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="119"/>
        <source>Object %1</source>
        <translation>Objet %1</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="178"/>
        <source>Merge Objects</source>
        <translation>Fusionner les objets</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="200"/>
        <source>Move Strokes to Object</source>
        <translation>Déplacer les traits vers un objet</translation>
    </message>
</context>
<context>
    <name>finbook::ui::OnionSkinEditor</name>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="14"/>
        <source>Show onion skin</source>
        <translation>Afficher la pelure d&apos;oignon</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="24"/>
        <source> %</source>
        <translation>&#xa0;%</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="27"/>
        <source>Frames before:</source>
        <translation>Images avant&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="28"/>
        <source>Frames after:</source>
        <translation>Images après&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="29"/>
        <source>Opacity of the nearest frame:</source>
        <translation>Opacité de l&apos;image la plus proche&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="30"/>
        <source>Tint before:</source>
        <translation>Teinte avant&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="31"/>
        <source>Tint after:</source>
        <translation>Teinte après&#xa0;:</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PalettePanel</name>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="44"/>
        <source>&quot;%1&quot; is not a palette Finbook can read: %2.</source>
        <translation>« %1 » n&apos;est pas une palette que Finbook sait lire : %2.</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="72"/>
        <source>Swatch name</source>
        <translation>Nom de la nuance</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="73"/>
        <source>The chosen swatch&apos;s name: type and press Return to rename it</source>
        <translation>Le nom de la nuance choisie : tapez puis Entrée pour la renommer</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="89"/>
        <source>Add the pen&apos;s colour to the palette</source>
        <translation>Ajouter la couleur du stylo à la palette</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="90"/>
        <source>Set</source>
        <translation>Appliquer</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="91"/>
        <source>Give the chosen swatch the pen&apos;s colour</source>
        <translation>Donner la couleur du stylo à la nuance choisie</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="93"/>
        <source>Move the chosen swatch one place earlier</source>
        <translation>Avancer la nuance choisie d&apos;une place</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="95"/>
        <source>Move the chosen swatch one place later</source>
        <translation>Reculer la nuance choisie d&apos;une place</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="97"/>
        <source>Delete the chosen swatch from the palette</source>
        <translation>Supprimer la nuance choisie de la palette</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="99"/>
        <source>Import, export, save and load palettes</source>
        <translation>Importer, exporter, enregistrer et charger des palettes</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="102"/>
        <source>&amp;Import GIMP Palette...</source>
        <translation>&amp;Importer une palette GIMP...</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="103"/>
        <source>&amp;Export GIMP Palette...</source>
        <translation>&amp;Exporter une palette GIMP...</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="105"/>
        <source>&amp;Save as User Palette...</source>
        <translation>&amp;Enregistrer comme palette personnelle...</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="106"/>
        <source>&amp;Load User Palette</source>
        <translation>&amp;Charger une palette personnelle</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="109"/>
        <source>&amp;Reset to Finbook&apos;s Colours</source>
        <translation>&amp;Revenir aux couleurs de Finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="110"/>
        <source>Reset Palette</source>
        <translation>Réinitialiser la palette</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="192"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="214"/>
        <source>A palette holds at most %1 colours.</source>
        <translation>Une palette contient au plus %1 couleurs.</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="219"/>
        <source>Add Swatch</source>
        <translation>Ajouter une nuance</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="230"/>
        <source>Recolour Swatch</source>
        <translation>Recolorer la nuance</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="240"/>
        <source>Delete Swatch</source>
        <translation>Supprimer la nuance</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="251"/>
        <location filename="../ui/src/palette/palette_panel.cpp" line="288"/>
        <source>Move Swatch</source>
        <translation>Déplacer la nuance</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="262"/>
        <source>Rename Swatch</source>
        <translation>Renommer la nuance</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="338"/>
        <source>it is far larger than a palette</source>
        <translation>il est bien plus gros qu&apos;une palette</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="347"/>
        <location filename="../ui/src/palette/palette_panel.cpp" line="410"/>
        <source>Import Palette</source>
        <translation>Importer la palette</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="354"/>
        <location filename="../ui/src/palette/palette_panel.cpp" line="376"/>
        <source>The palette could not be saved as &quot;%1&quot;: %2</source>
        <translation>La palette n&apos;a pas pu être enregistrée sous « %1 » : %2</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="368"/>
        <source>A user palette needs a name.</source>
        <translation>Une palette personnelle a besoin d&apos;un nom.</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="370"/>
        <source>The folder for user palettes (%1) could not be made.</source>
        <translation>Le dossier des palettes personnelles (%1) n&apos;a pas pu être créé.</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="391"/>
        <source>(no user palettes yet)</source>
        <translation>(pas encore de palette personnelle)</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="398"/>
        <source>Load Palette</source>
        <translation>Charger la palette</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="404"/>
        <source>Import GIMP Palette</source>
        <translation>Importer une palette GIMP</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="405"/>
        <source>GIMP palettes (*.gpl);;All files (*)</source>
        <translation>Palettes GIMP (*.gpl);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="415"/>
        <source>Export GIMP Palette</source>
        <translation>Exporter une palette GIMP</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="417"/>
        <source>GIMP palettes (*.gpl)</source>
        <translation>Palettes GIMP (*.gpl)</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="424"/>
        <source>Export Palette</source>
        <translation>Exporter la palette</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="426"/>
        <source>Palette saved as &quot;%1&quot;.</source>
        <translation>Palette enregistrée sous « %1 ».</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="433"/>
        <source>Save as User Palette</source>
        <translation>Enregistrer comme palette personnelle</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="433"/>
        <source>Name of the palette:</source>
        <translation>Nom de la palette :</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="439"/>
        <source>Save Palette</source>
        <translation>Enregistrer la palette</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="441"/>
        <source>Saved as the user palette &quot;%1&quot;; Palette &gt; Load User Palette brings it into any drawing.</source>
        <translation>Enregistrée comme palette personnelle « %1 » ; Palette &gt; Charger une palette personnelle l&apos;amène dans tout dessin.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PenTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_pen.h" line="40"/>
        <source>Pen</source>
        <translation>Stylo</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_pen.h" line="43"/>
        <source>draw lines; the pen&apos;s pressure sets their width</source>
        <translation>tracer des traits ; la pression du stylet règle leur épaisseur</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_pen.cpp" line="117"/>
        <source>Draw Stroke</source>
        <translation>Tracer un trait</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PinTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/pins/tool_pin.h" line="19"/>
        <source>Pin</source>
        <translation>Épingle</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/pins/tool_pin.h" line="22"/>
        <source>pin points and drag them: the drawing bends as rigidly as it can</source>
        <translation>épingler des points et les tirer : le dessin plie aussi rigidement que possible</translation>
    </message>
    <message>
        <location filename="../ui/src/pins/tool_pin.cpp" line="162"/>
        <source>Click on a visible, unlocked drawing to pin it.</source>
        <translation>Cliquez sur un dessin visible et non verrouillé pour y poser une épingle.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PlaybackController</name>
    <message>
        <location filename="../ui/src/timeline/playback_controller.cpp" line="61"/>
        <location filename="../ui/src/timeline/playback_controller.cpp" line="226"/>
        <source>Pl&amp;ay</source>
        <translation>&amp;Lecture</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/playback_controller.cpp" line="65"/>
        <source>Play or pause the animation</source>
        <translation>Lire l&apos;animation ou la mettre en pause</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/playback_controller.cpp" line="73"/>
        <source>L&amp;oop</source>
        <translation>Lecture en &amp;boucle</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/playback_controller.cpp" line="77"/>
        <source>Start again at the end of the play range</source>
        <translation>Recommencer au début à la fin de la plage de lecture</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/playback_controller.cpp" line="226"/>
        <source>P&amp;ause</source>
        <translation>Pa&amp;use</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PreferencesDialog</name>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="21"/>
        <source>Preferences</source>
        <translation>Préférences</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="25"/>
        <source>New Documents</source>
        <translation>Nouveaux documents</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="26"/>
        <source>Onion Skin</source>
        <translation>Pelure d&apos;oignon</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="27"/>
        <source>Keyboard Shortcuts</source>
        <translation>Raccourcis clavier</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="42"/>
        <source> fps</source>
        <translation> i/s</translation>
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
        <translation>Jamais</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="57"/>
        <source>How often Finbook keeps a recovery copy of unsaved changes, offered at the next start if Finbook did not close normally.</source>
        <translation>Fréquence à laquelle Finbook conserve une copie de récupération des modifications non enregistrées, proposée au démarrage suivant si Finbook ne s&apos;est pas fermé normalement.</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="61"/>
        <source>Frame rate:</source>
        <translation>Fréquence d&apos;images&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="62"/>
        <source>Canvas width:</source>
        <translation>Largeur du canevas&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="63"/>
        <source>Canvas height:</source>
        <translation>Hauteur du canevas&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="64"/>
        <source>Autosave every:</source>
        <translation>Enregistrement automatique&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="86"/>
        <source>Conflicting Shortcuts</source>
        <translation>Raccourcis en conflit</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="87"/>
        <source>Two or more actions share a shortcut. Change or clear the shortcuts marked in red, then press OK again.</source>
        <translation>Plusieurs actions partagent un raccourci. Modifiez ou effacez les raccourcis marqués en rouge, puis appuyez à nouveau sur OK.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::RecoveryDialog</name>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="17"/>
        <source>Recover Unsaved Work</source>
        <translation>Récupérer le travail non enregistré</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="18"/>
        <source>Finbook did not close normally last time. It kept these copies of work that was not saved:</source>
        <translation>Finbook ne s&apos;est pas fermé normalement la dernière fois. Il a conservé ces copies de travail non enregistré&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="31"/>
        <source>&amp;Restore</source>
        <translation>&amp;Restaurer</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="32"/>
        <source>&amp;Discard</source>
        <translation>&amp;Supprimer</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="33"/>
        <source>&amp;Later</source>
        <translation>Plus &amp;tard</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="35"/>
        <source>Open the copy as an unsaved animation</source>
        <translation>Ouvrir la copie comme une animation non enregistrée</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="36"/>
        <source>Delete the copy for good</source>
        <translation>Supprimer définitivement la copie</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="37"/>
        <source>Keep the copies and ask again at the next start</source>
        <translation>Conserver les copies et redemander au prochain démarrage</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="56"/>
        <source>Untitled</source>
        <translation>Sans titre</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="58"/>
        <source>%1 — %2 — %n frame(s)</source>
        <translation>
            <numerusform>%1 — %2 — %n image</numerusform>
            <numerusform>%1 — %2 — %n images</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::ui::ReferencePanel</name>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="39"/>
        <source>&amp;Visible</source>
        <translation>&amp;Visible</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="40"/>
        <source>Loc&amp;ked</source>
        <translation>&amp;Verrouillée</translation>
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
        <translation> i/s</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="48"/>
        <source>Document rate</source>
        <translation>Cadence du document</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="108"/>
        <source>Picture rate:</source>
        <translation>Cadence des images :</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="110"/>
        <source>Pictures per second of animation. At the document&apos;s rate every frame shows the next picture; a lower rate holds each picture for several frames.</source>
        <translation>Images par seconde d&apos;animation. À la cadence du document, chaque frame montre l&apos;image suivante ; une cadence plus basse garde chaque image pendant plusieurs frames.</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="112"/>
        <source>Animation frames per second of video. At the document&apos;s rate the video plays in real time; a higher rate plays it slower, spreading each second over more frames.</source>
        <translation>Frames d&apos;animation par seconde de vidéo. À la cadence du document, la vidéo défile en temps réel ; une cadence plus haute la ralentit, en étalant chaque seconde sur plus de frames.</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="51"/>
        <source>&amp;Remove Reference</source>
        <translation>&amp;Retirer la référence</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="57"/>
        <source>Opacity:</source>
        <translation>Opacité :</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="58"/>
        <source>Centre X:</source>
        <translation>Centre X :</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="59"/>
        <source>Centre Y:</source>
        <translation>Centre Y :</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="60"/>
        <source>Scale:</source>
        <translation>Échelle :</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="61"/>
        <source>Rotation:</source>
        <translation>Rotation :</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="108"/>
        <source>Video rate:</source>
        <translation>Cadence vidéo :</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="90"/>
        <source>No reference. File → Import Reference… puts a picture or a video under the drawing.</source>
        <translation>Aucune référence. Fichier → Importer une référence… place une image ou une vidéo sous le dessin.</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="167"/>
        <source>The reference could not be placed on the canvas.</source>
        <translation>La référence n’a pas pu être placée sur la toile.</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="175"/>
        <location filename="../ui/src/reference/reference_panel.cpp" line="182"/>
        <source>Import Reference</source>
        <translation>Importer une référence</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/reference/reference_panel.cpp" line="183"/>
        <source>“%1” is one of %n numbered pictures (%2 … %3). Import them all as a sequence, one picture per frame?</source>
        <translation>
            <numerusform>« %1 » fait partie de %n image numérotée (%2 … %3). Les importer toutes en séquence, une image par trame ?</numerusform>
            <numerusform>« %1 » fait partie de %n images numérotées (%2 … %3). Les importer toutes en séquence, une image par trame ?</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="196"/>
        <source>Pictures and videos (*.png *.jpg *.jpeg *.webp *.bmp *.gif *.tif *.tiff *.mp4 *.m4v *.mov *.mkv *.webm *.avi);;All files (*)</source>
        <translation>Images et vidéos (*.png *.jpg *.jpeg *.webp *.bmp *.gif *.tif *.tiff *.mp4 *.m4v *.mov *.mkv *.webm *.avi);;Tous les fichiers (*)</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ReferenceTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/reference/tool_reference.h" line="21"/>
        <source>Move Reference</source>
        <translation>Déplacer la référence</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/reference/tool_reference.h" line="24"/>
        <source>move, scale and turn the reference picture</source>
        <translation>déplacer, mettre à l&apos;échelle et tourner l&apos;image de référence</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SelectTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_select.h" line="28"/>
        <source>Select</source>
        <translation>Sélection</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_select.h" line="31"/>
        <source>lasso lines, then move, turn or scale them</source>
        <translation>entourer des traits au lasso, puis les déplacer, les tourner ou les mettre à l&apos;échelle</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="400"/>
        <source>The strokes cannot be transformed that far.</source>
        <translation>Les traits ne peuvent pas être transformés à ce point.</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="409"/>
        <source>Move Strokes</source>
        <translation>Déplacer les traits</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="409"/>
        <source>Move Picture</source>
        <translation>Déplacer l’image</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="410"/>
        <source>Rotate Strokes</source>
        <translation>Faire pivoter les traits</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="410"/>
        <source>Rotate Picture</source>
        <translation>Faire pivoter l’image</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="411"/>
        <source>Scale Strokes</source>
        <translation>Redimensionner les traits</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="411"/>
        <source>Scale Picture</source>
        <translation>Redimensionner l’image</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="418"/>
        <source>The picture cannot be transformed that far.</source>
        <translation>L’image ne peut pas être transformée à ce point.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ShadingPanel</name>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="25"/>
        <source>Flat</source>
        <translation>Aplat</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="26"/>
        <source>Cel, two tones</source>
        <translation>Cel, deux tons</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="27"/>
        <source>Cel, three tones</source>
        <translation>Cel, trois tons</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="28"/>
        <source>Smooth</source>
        <translation>Lisse</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="29"/>
        <source>Shade the current object&apos;s fills from its rounded shape, in every frame where the object appears (objects of the same name)</source>
        <translation>Ombrer les remplissages de l’objet courant d’après sa forme arrondie, dans chaque image où l’objet apparaît (les objets de même nom)</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="31"/>
        <source>Fills:</source>
        <translation>Remplissages&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="32"/>
        <source>Rim light</source>
        <translation>Lumière de contour</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="34"/>
        <source>A light edge on the side away from the light</source>
        <translation>Un bord clair du côté opposé à la lumière</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="42"/>
        <source>Where the light comes from on screen: 0° from the right, 90° from above, 180° from the left</source>
        <translation>D’où vient la lumière à l’écran&#xa0;: 0° de la droite, 90° du haut, 180° de la gauche</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="44"/>
        <source>Light direction:</source>
        <translation>Direction de la lumière&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="50"/>
        <source>How high the light stands above the drawing: 0° grazes it, 90° shines from the viewer</source>
        <translation>Hauteur de la lumière au-dessus du dessin&#xa0;: 0° la rase, 90° éclaire depuis le spectateur</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="52"/>
        <source>Light height:</source>
        <translation>Hauteur de la lumière&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="89"/>
        <source>Fill regions of the current object with the Fill tool to shade them.</source>
        <translation>Remplissez des zones de l’objet courant avec l’outil Remplissage pour les ombrer.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ShortcutEditor</name>
    <message>
        <location filename="../ui/src/dialogs/shortcut_editor.cpp" line="31"/>
        <source>Action</source>
        <translation>Action</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcut_editor.cpp" line="31"/>
        <source>Shortcut</source>
        <translation>Raccourci</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcut_editor.cpp" line="31"/>
        <source>Alternative</source>
        <translation>Secondaire</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcut_editor.cpp" line="72"/>
        <source>Restore Defaults</source>
        <translation>Rétablir les valeurs par défaut</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcut_editor.cpp" line="132"/>
        <source>%1 is used by: %2</source>
        <translation>%1 est utilisé par&#xa0;: %2</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcut_editor.cpp" line="143"/>
        <source>Conflicting shortcuts:</source>
        <translation>Raccourcis en conflit&#xa0;:</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ShortcutsDialog</name>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="20"/>
        <source>Keyboard Shortcuts</source>
        <translation>Raccourcis clavier</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="26"/>
        <source>Pan the view</source>
        <translation>Faire défiler la vue</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="26"/>
        <source>Space + drag, or middle button drag</source>
        <translation>Espace + glisser, ou glisser avec le bouton du milieu</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="27"/>
        <source>Zoom about the cursor</source>
        <translation>Zoomer autour du curseur</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="27"/>
        <source>Mouse wheel</source>
        <translation>Molette de la souris</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="31"/>
        <source>Action</source>
        <translation>Action</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="31"/>
        <source>Shortcut</source>
        <translation>Raccourci</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="53"/>
        <source>Filter</source>
        <translation>Filtrer</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SkeletonPanel</name>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="25"/>
        <source>Bone complexity</source>
        <translation>Complexité des os</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="25"/>
        <source>Merge junctions</source>
        <translation>Fusionner les jonctions</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="25"/>
        <source>Prune branches</source>
        <translation>Élaguer les branches</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="26"/>
        <source>Collapse short bones</source>
        <translation>Réduire les os courts</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="27"/>
        <source>Bones</source>
        <translation>Os</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="27"/>
        <source>Merge</source>
        <translation>Fusion</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="27"/>
        <source>Prune</source>
        <translation>Élaguer</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="27"/>
        <source>Collapse</source>
        <translation>Réduire</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="29"/>
        <source>More bones follow the shape more closely</source>
        <translation>Plus il y a d&apos;os, plus ils suivent fidèlement la forme</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="30"/>
        <source>Junctions closer than this become one</source>
        <translation>Les jonctions plus proches que cette distance n&apos;en forment plus qu&apos;une</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="31"/>
        <source>Remove side branches shorter than this</source>
        <translation>Supprimer les branches latérales plus courtes que cette longueur</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="32"/>
        <source>Collapse inner bones shorter than this into one joint</source>
        <translation>Réduire en une seule articulation les os internes plus courts que cette longueur</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="41"/>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="55"/>
        <source>Pick the Bone tool (K) and click an object to give it a skeleton.</source>
        <translation>Choisissez l&apos;outil Os (K) et cliquez sur un objet pour lui donner un squelette.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SoundController</name>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="42"/>
        <source>Import Soun&amp;d...</source>
        <translation>Impor&amp;ter un son...</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="44"/>
        <source>Add a sound file to the soundtrack, starting at the current frame</source>
        <translation>Ajouter un fichier son à la bande son, à partir de l&apos;image actuelle</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="47"/>
        <source>Import Sound</source>
        <translation>Importer un son</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="48"/>
        <source>Sound files (*.wav *.flac *.mp3 *.ogg *.oga *.opus *.m4a *.aac);;All files (*)</source>
        <translation>Fichiers son (*.wav *.flac *.mp3 *.ogg *.oga *.opus *.m4a *.aac);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="74"/>
        <source>The sound &quot;%1&quot; cannot be played: %2</source>
        <translation>Le son « %1 » ne peut pas être lu : %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/sound/sound_controller.cpp" line="77"/>
        <source>%n sound(s) cannot be played; &quot;%1&quot;: %2</source>
        <translation>
            <numerusform>%n son ne peut pas être lu ; « %1 » : %2</numerusform>
            <numerusform>%n sons ne peuvent pas être lus ; « %1 » : %2</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="100"/>
        <location filename="../ui/src/sound/sound_controller.cpp" line="140"/>
        <source>Cannot Import Sound</source>
        <translation>Impossible d’importer le son</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="100"/>
        <source>Cannot import &quot;%1&quot;: %2</source>
        <translation>Impossible d’importer « %1 » : %2</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="103"/>
        <source>it is not a file.</source>
        <translation>ce n&apos;est pas un fichier.</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="107"/>
        <source>it is larger than %1 MB.</source>
        <translation>il dépasse %1 Mo.</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="116"/>
        <source>Reading &quot;%1&quot;…</source>
        <translation>Lecture de « %1 »…</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="141"/>
        <source>Cannot import &quot;%1&quot;: %2 Nothing was changed.</source>
        <translation>Impossible d’importer « %1 » : %2 Rien n’a été modifié.</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="154"/>
        <location filename="../ui/src/sound/sound_controller.cpp" line="156"/>
        <source>Imported &quot;%1&quot; (%2 s).</source>
        <translation>« %1 » importé (%2 s).</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="183"/>
        <source>Sound Volume</source>
        <translation>Volume du son</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="183"/>
        <source>Volume of &quot;%1&quot; (%):</source>
        <translation>Volume de « %1 » (%) :</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SoundPlayer</name>
    <message>
        <location filename="../ui/src/sound/sound_player.cpp" line="69"/>
        <source>No audio output was found: playing without sound.</source>
        <translation>Aucune sortie audio trouvée : lecture sans son.</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_player.cpp" line="80"/>
        <source>The audio output failed: playing without sound.</source>
        <translation>La sortie audio a échoué : lecture sans son.</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SoundRow</name>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="37"/>
        <source>The soundtrack: drag a sound to move it, right click for its volume</source>
        <translation>La bande son : faites glisser un son pour le déplacer, clic droit pour son volume</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="133"/>
        <source>+%1 s after the last frame (not played)</source>
        <translation>+%1 s après la dernière image (non joué)</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="163"/>
        <source>No sound: File → Import Sound…</source>
        <translation>Aucun son : Fichier → Importer un son…</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="219"/>
        <source>%1 (cannot be played)</source>
        <translation>%1 (illisible)</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="221"/>
        <source>%1 (reading…)</source>
        <translation>%1 (lecture…)</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="223"/>
        <source>%1 (muted)</source>
        <translation>%1 (coupé)</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="299"/>
        <source>&amp;Mute</source>
        <translation>&amp;Couper le son</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="304"/>
        <source>&amp;Volume...</source>
        <translation>&amp;Volume...</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="306"/>
        <source>Delete &amp;Sound</source>
        <translation>&amp;Supprimer le son</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SwapActions</name>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="24"/>
        <source>Make S&amp;wappable</source>
        <translation>Rendre &amp;interchangeable</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="26"/>
        <source>New Mout&amp;h Chart</source>
        <translation>Nouvelle &amp;planche de bouches</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="29"/>
        <source>&amp;Previous Drawing</source>
        <translation>Dessin pré&amp;cédent</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="32"/>
        <source>Ne&amp;xt Drawing</source>
        <translation>Dessin s&amp;uivant</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="22"/>
        <source>Show Dr&amp;awing</source>
        <translation>&amp;Afficher le dessin</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="35"/>
        <source>New Drawing in S&amp;et</source>
        <translation>Nouveau dessin dans &amp;le jeu</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="38"/>
        <source>D&amp;uplicate Drawing in Set</source>
        <translation>Dupli&amp;quer le dessin dans le jeu</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="40"/>
        <source>&amp;Rename Drawing...</source>
        <translation>Ren&amp;ommer le dessin…</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="42"/>
        <source>Remove Drawing from Se&amp;t</source>
        <translation>Re&amp;tirer le dessin du jeu</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="44"/>
        <source>Make Drawing &amp;Independent</source>
        <translation>&amp;Garder le dessin pour cette image</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="47"/>
        <source>Make the object&apos;s drawing the first of a set it swaps between, frame by frame (mouths, hands, blinks)</source>
        <translation>Faire du dessin de l&apos;objet le premier d&apos;un jeu entre lesquels il change, image par image (bouches, mains, clignements)</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="50"/>
        <source>A new object showing the nine mouth shapes lip sync uses</source>
        <translation>Un nouvel objet montrant les neuf formes de bouche de la synchro labiale</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="52"/>
        <source>This frame keeps its drawing as its own: edits of it no longer reach the other frames</source>
        <translation>Cette image garde son dessin pour elle : ses modifications n&apos;atteignent plus les autres images</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="125"/>
        <source>(not swappable)</source>
        <translation>(pas interchangeable)</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="129"/>
        <source>(unnamed)</source>
        <translation>(sans nom)</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="162"/>
        <source>&quot;%1&quot; is swappable: add drawings with Object &gt; New Drawing in Set, and pick one per frame with [ and ]</source>
        <translation>« %1 » est interchangeable : ajoutez des dessins avec Objet &gt; Nouveau dessin dans le jeu, et choisissez-en un par image avec [ et ]</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="190"/>
        <source>New Mouth Chart</source>
        <translation>Nouvelle planche de bouches</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="191"/>
        <location filename="../ui/src/swap/swap_actions.cpp" line="195"/>
        <source>Mouth</source>
        <translation>Bouche</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="201"/>
        <source>A mouth chart on its own layer: nine mouth shapes to redraw in your style; [ and ] swap them, Deform &gt; Lip Sync keys them from the soundtrack</source>
        <translation>Une planche de bouches sur son propre calque : neuf formes à redessiner à votre façon ; [ et ] les échangent, Déformer &gt; Synchro labiale les pose d&apos;après la bande son</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="226"/>
        <source>Rename Drawing</source>
        <translation>Renommer le dessin</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="226"/>
        <source>Name of the drawing:</source>
        <translation>Nom du dessin :</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="273"/>
        <source>Drawing &quot;%1&quot;</source>
        <translation>Dessin « %1 »</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SwapPicker</name>
    <message>
        <location filename="../ui/src/swap/swap_picker.cpp" line="15"/>
        <source>Drawing:</source>
        <translation>Dessin :</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_picker.cpp" line="20"/>
        <source>The drawing this object shows in this frame ([ and ] step through them)</source>
        <translation>Le dessin que cet objet montre dans cette image ([ et ] les parcourent)</translation>
    </message>
</context>
<context>
    <name>finbook::ui::TimelineView</name>
    <message>
        <location filename="../ui/src/timeline/timeline_view.cpp" line="266"/>
        <source>Drag along the frame numbers to scrub through the animation</source>
        <translation>Glissez le long des numéros d&apos;image pour parcourir l&apos;animation</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_view.cpp" line="268"/>
        <source>Click to show this frame; drag the picture to move the frame elsewhere; Ctrl- or Shift-click to pick several</source>
        <translation>Cliquez pour afficher cette image ; faites glisser l&apos;image pour la déplacer ailleurs ; Ctrl- ou Maj-clic pour en choisir plusieurs</translation>
    </message>
</context>
<context>
    <name>finbook::ui::TimelineWidget</name>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="91"/>
        <source>Onion Skin</source>
        <translation>Pelure d&apos;oignon</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="92"/>
        <source>Show neighbouring frames faintly while drawing</source>
        <translation>Afficher les images voisines en transparence pendant le dessin</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="108"/>
        <source>Before:</source>
        <translation>Avant&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="109"/>
        <source>How many earlier frames the onion skin shows</source>
        <translation>Nombre d&apos;images précédentes que montre la pelure d&apos;oignon</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="110"/>
        <source>After:</source>
        <translation>Après&#xa0;:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="111"/>
        <source>How many later frames the onion skin shows</source>
        <translation>Nombre d&apos;images suivantes que montre la pelure d&apos;oignon</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="142"/>
        <source>Frame %1 of %2 · %3 fps</source>
        <translation>Image %1 sur %2 · %3 i/s</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ToolOptionsBar</name>
    <message>
        <location filename="../ui/src/window/tool_options_bar.cpp" line="11"/>
        <source>Tool Options</source>
        <translation>Options de l&apos;outil</translation>
    </message>
    <message>
        <location filename="../ui/src/window/tool_options_bar.cpp" line="56"/>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
</context>
<context>
    <name>finbook::ui::WelcomeDialog</name>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="37"/>
        <source>Show this page whenever Finbook starts</source>
        <translation>Afficher cette page à chaque démarrage de Finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="40"/>
        <source>Welcome to Finbook</source>
        <translation>Bienvenue dans Finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="50"/>
        <source>&amp;New Animation</source>
        <translation>&amp;Nouvelle animation</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="50"/>
        <source>Start an empty animation</source>
        <translation>Commencer une animation vide</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="51"/>
        <source>&amp;Open...</source>
        <translation>&amp;Ouvrir...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="51"/>
        <source>Open a .finbook file</source>
        <translation>Ouvrir un fichier .finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="52"/>
        <source>Open the &amp;Example</source>
        <translation>Ouvrir l&apos;&amp;exemple</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="53"/>
        <source>A short walk cycle drawn with Finbook, to look at and change</source>
        <translation>Un court cycle de marche dessiné avec Finbook, à regarder et à modifier</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="54"/>
        <source>Read the &amp;Manual</source>
        <translation>Lire le &amp;manuel</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="55"/>
        <source>The Finbook Manual (F1 opens it at the tool in hand)</source>
        <translation>Le manuel de Finbook (F1 l&apos;ouvre à l&apos;outil en main)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="63"/>
        <source>(no recent files yet)</source>
        <translation>(pas encore de fichier récent)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="70"/>
        <source>&lt;h2&gt;Draw — bend — play&lt;/h2&gt;&lt;p&gt;&lt;b&gt;1. Draw.&lt;/b&gt; Take the pen (&lt;b&gt;B&lt;/b&gt;) and draw a character; a tablet&apos;s pressure shapes the line. Close its outline loosely: small gaps close by themselves. Pick a colour in the Palette and click inside with the fill (&lt;b&gt;F&lt;/b&gt;).&lt;/p&gt;&lt;p&gt;&lt;b&gt;2. Bend.&lt;/b&gt; Instead of drawing the next frame again, duplicate the frame (&lt;b&gt;Ctrl+D&lt;/b&gt;) and bend the copy: click the drawing with the bone tool (&lt;b&gt;K&lt;/b&gt;) and drag a bone, or put pins on it (&lt;b&gt;P&lt;/b&gt;) and drag one; the rest follows as if drawn on rubber. The bent drawing is lines again: keep drawing on it.&lt;/p&gt;&lt;p&gt;&lt;b&gt;3. Play.&lt;/b&gt; Press &lt;b&gt;Return&lt;/b&gt; to play; Frame → In-betweens fills the frames between two poses. Onion skin (&lt;b&gt;O&lt;/b&gt;) shows the neighbours faintly. Save with &lt;b&gt;Ctrl+S&lt;/b&gt;, export a GIF, a video or a Lottie animation with File → Export.&lt;/p&gt;&lt;p&gt;&lt;a href=&quot;getting-started.md&quot;&gt;Read “Getting Started” in the manual&lt;/a&gt;, or press &lt;b&gt;F1&lt;/b&gt; at any time for the page of the tool in hand.&lt;/p&gt;</source>
        <translation>&lt;h2&gt;Dessiner — plier — jouer&lt;/h2&gt;&lt;p&gt;&lt;b&gt;1. Dessiner.&lt;/b&gt; Prenez le stylo (&lt;b&gt;B&lt;/b&gt;) et dessinez un personnage ; la pression d&apos;une tablette forme le trait. Fermez son contour sans soin : les petits écarts se ferment seuls. Choisissez une couleur dans la Palette et cliquez dedans avec le remplissage (&lt;b&gt;F&lt;/b&gt;).&lt;/p&gt;&lt;p&gt;&lt;b&gt;2. Plier.&lt;/b&gt; Au lieu de redessiner l&apos;image suivante, dupliquez l&apos;image (&lt;b&gt;Ctrl+D&lt;/b&gt;) et pliez la copie : cliquez le dessin avec l&apos;outil os (&lt;b&gt;K&lt;/b&gt;) et tirez un os, ou posez des épingles (&lt;b&gt;P&lt;/b&gt;) et tirez-en une ; le reste suit comme dessiné sur du caoutchouc. Le dessin plié redevient des traits : continuez à dessiner dessus.&lt;/p&gt;&lt;p&gt;&lt;b&gt;3. Jouer.&lt;/b&gt; &lt;b&gt;Entrée&lt;/b&gt; joue l&apos;animation ; Image → Intervalles remplit les images entre deux poses. La pelure d&apos;oignon (&lt;b&gt;O&lt;/b&gt;) montre les voisines en pâle. Enregistrez avec &lt;b&gt;Ctrl+S&lt;/b&gt;, exportez un GIF, une vidéo ou une animation Lottie avec Fichier → Exporter.&lt;/p&gt;&lt;p&gt;&lt;a href=&quot;getting-started.md&quot;&gt;Lire « Getting Started » dans le manuel&lt;/a&gt;, ou appuyez sur &lt;b&gt;F1&lt;/b&gt; à tout moment pour la page de l&apos;outil en main.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="91"/>
        <source>Recent files:</source>
        <translation>Fichiers récents :</translation>
    </message>
</context>
</TS>
