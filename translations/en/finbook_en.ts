<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>Deformation</name>
    <message numerus="yes">
        <location filename="../../model/src/cage/cage_setup.cpp" line="41"/>
        <source>%n stroke point(s) lie outside the cage; move its corners out so it encloses the drawing.</source>
        <translation>
            <numerusform>%n stroke point lies outside the cage; move its corners out so it encloses the drawing.</numerusform>
            <numerusform>%n stroke points lie outside the cage; move its corners out so it encloses the drawing.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>Export</name>
    <message numerus="yes">
        <location filename="../../model/src/export/ffmpeg_encoder.cpp" line="283"/>
        <source>ffmpeg made no progress for %n second(s) and was stopped; nothing was written. Check that ffmpeg works, then export again.</source>
        <translation>
            <numerusform>ffmpeg made no progress for %n second and was stopped; nothing was written. Check that ffmpeg works, then export again.</numerusform>
            <numerusform>ffmpeg made no progress for %n seconds and was stopped; nothing was written. Check that ffmpeg works, then export again.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../model/src/export/export_model.cpp" line="110"/>
        <source>%n object(s) of frame %1 could not be made 3D (a dot or a straight line has no area to inflate; a drawing far off the page cannot be meshed) and were left out.</source>
        <translation>
            <numerusform>%n object of frame %1 could not be made 3D (a dot or a straight line has no area to inflate; a drawing far off the page cannot be meshed) and was left out.</numerusform>
            <numerusform>%n objects of frame %1 could not be made 3D (a dot or a straight line has no area to inflate; a drawing far off the page cannot be meshed) and were left out.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../model/src/export/export_model.cpp" line="115"/>
        <source>%n object(s) of frame %1 could not be made 3D (a dot or a straight line has no area to inflate) and were left out.</source>
        <translation>
            <numerusform>%n object of frame %1 could not be made 3D (a dot or a straight line has no area to inflate) and was left out.</numerusform>
            <numerusform>%n objects of frame %1 could not be made 3D (a dot or a straight line has no area to inflate) and were left out.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../model/src/export/exporter.cpp" line="268"/>
        <source>%n more sound clip(s) are left out too.</source>
        <translation>
            <numerusform>%n more sound clip is left out too.</numerusform>
            <numerusform>%n more sound clips are left out too.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>FinbookFile</name>
    <message numerus="yes">
        <location filename="../../model/src/finbook_file_reader_frames.cpp" line="341"/>
        <source>its pose has %n stroke(s) but the object has %1</source>
        <translation>
            <numerusform>its pose has %n stroke but the object has %1</numerusform>
            <numerusform>its pose has %n strokes but the object has %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../model/src/finbook_file_reader_frames.cpp" line="348"/>
        <source>stroke %1 has %n point(s) but its pose has %2</source>
        <translation>
            <numerusform>stroke %1 has %n point but its pose has %2</numerusform>
            <numerusform>stroke %1 has %n points but its pose has %2</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../model/src/finbook_file_reader_tables.cpp" line="48"/>
        <source>%n point(s) with a non-finite coordinate are left out</source>
        <translation>
            <numerusform>%n point with a non-finite coordinate is left out</numerusform>
            <numerusform>%n points with a non-finite coordinate are left out</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../model/src/finbook_file_recover.cpp" line="126"/>
        <source>%n missing or repeated id(s) were replaced by new ones</source>
        <translation>
            <numerusform>%n missing or repeated id was replaced by a new one</numerusform>
            <numerusform>%n missing or repeated ids were replaced by new ones</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ObjectListModel</name>
    <message numerus="yes">
        <location filename="../../model/src/object_list_model.cpp" line="170"/>
        <source>%1: %n stroke(s)</source>
        <translation>
            <numerusform>%1: %n stroke</numerusform>
            <numerusform>%1: %n strokes</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>Reference</name>
    <message numerus="yes">
        <location filename="../../model/src/reference/reference_sequence.cpp" line="108"/>
        <source>%1 and %n more</source>
        <extracomment>%1 is the first file&apos;s name, %n how many pictures follow it</extracomment>
        <translation>
            <numerusform>%1 and %n more</numerusform>
            <numerusform>%1 and %n more</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::model::FrameListModel</name>
    <message numerus="yes">
        <location filename="../../model/src/frame_list_model.cpp" line="151"/>
        <source>Frame %1, held for %n frame(s)</source>
        <translation>
            <numerusform>Frame %1, held for %n frame</numerusform>
            <numerusform>Frame %1, held for %n frames</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::ui::BoneTool</name>
    <message numerus="yes">
        <location filename="../../ui/src/skeleton/tool_bone_menu.cpp" line="279"/>
        <source>Joined %n part(s).</source>
        <translation>
            <numerusform>Joined %n part.</numerusform>
            <numerusform>Joined %n parts.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::ui::DeformActions</name>
    <message numerus="yes">
        <location filename="../../ui/src/rig/deform_actions.cpp" line="57"/>
        <source>The pins fold the drawing: %n triangle(s) of its mesh turned over where the pins leave no room (View → Show Mesh shows them red)</source>
        <translation>
            <numerusform>The pins fold the drawing: %n triangle of its mesh turned over where the pins leave no room (View → Show Mesh shows it red)</numerusform>
            <numerusform>The pins fold the drawing: %n triangles of its mesh turned over where the pins leave no room (View → Show Mesh shows them red)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::ui::ExportDialog</name>
    <message numerus="yes">
        <location filename="../../ui/src/export/export_dialog_run.cpp" line="86"/>
        <source>Exported %n file(s) to %1</source>
        <translation>
            <numerusform>Exported %n file to %1</numerusform>
            <numerusform>Exported %n files to %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/src/export/export_dialog_run.cpp" line="125"/>
        <source>%n file(s) at the target already exist, such as &quot;%1&quot;. Replace them?</source>
        <translation>
            <numerusform>%n file at the target already exists, &quot;%1&quot;. Replace it?</numerusform>
            <numerusform>%n files at the target already exist, such as &quot;%1&quot;. Replace them?</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::ui::FrameActions</name>
    <message numerus="yes">
        <location filename="../../ui/src/timeline/frame_actions.cpp" line="126"/>
        <source>Delete %n Frame(s)</source>
        <translation>
            <numerusform>Delete %n Frame</numerusform>
            <numerusform>Delete %n Frames</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::ui::LipSyncDialog</name>
    <message numerus="yes">
        <location filename="../../ui/src/lipsync/lip_sync_dialog.cpp" line="246"/>
        <source>Keyed the mouth on %n frame(s), %1.</source>
        <translation>
            <numerusform>Keyed the mouth on %n frame, %1.</numerusform>
            <numerusform>Keyed the mouth on %n frames, %1.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/src/lipsync/lip_sync_dialog.cpp" line="248"/>
        <source>%n frame(s) of the mouth&apos;s layer hold no mouth and were left as they were.</source>
        <translation>
            <numerusform>%n frame of the mouth&apos;s layer holds no mouth and was left as it was.</numerusform>
            <numerusform>%n frames of the mouth&apos;s layer hold no mouth and were left as they were.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::ui::MainWindow</name>
    <message numerus="yes">
        <location filename="../../ui/src/window/main_window_files.cpp" line="145"/>
        <source>Opened what was readable of %1 (%n problem(s) repaired); save it under a new name.</source>
        <translation>
            <numerusform>Opened what was readable of %1 (%n problem repaired); save it under a new name.</numerusform>
            <numerusform>Opened what was readable of %1 (%n problems repaired); save it under a new name.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../ui/src/window/main_window_files.cpp" line="348"/>
        <source>Imported &quot;%1&quot;: %n picture object(s).</source>
        <translation>
            <numerusform>Imported &quot;%1&quot;: %n picture object.</numerusform>
            <numerusform>Imported &quot;%1&quot;: %n picture objects.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::ui::RecoveryDialog</name>
    <message numerus="yes">
        <location filename="../../ui/src/recovery/recovery_dialog.cpp" line="58"/>
        <source>%1 — %2 — %n frame(s)</source>
        <translation>
            <numerusform>%1 — %2 — %n frame</numerusform>
            <numerusform>%1 — %2 — %n frames</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::ui::ReferencePanel</name>
    <message numerus="yes">
        <location filename="../../ui/src/reference/reference_panel.cpp" line="183"/>
        <source>“%1” is one of %n numbered pictures (%2 … %3). Import them all as a sequence, one picture per frame?</source>
        <translation>
            <numerusform>“%1” is one of %n numbered picture (%2 … %3). Import it as a sequence, one picture per frame?</numerusform>
            <numerusform>“%1” is one of %n numbered pictures (%2 … %3). Import them all as a sequence, one picture per frame?</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::ui::SoundController</name>
    <message numerus="yes">
        <location filename="../../ui/src/sound/sound_controller.cpp" line="77"/>
        <source>%n sound(s) cannot be played; &quot;%1&quot;: %2</source>
        <translation>
            <numerusform>%n sound cannot be played; &quot;%1&quot;: %2</numerusform>
            <numerusform>%n sounds cannot be played; &quot;%1&quot;: %2</numerusform>
        </translation>
    </message>
</context>
</TS>
