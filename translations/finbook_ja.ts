<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ja_JP">
<context>
    <name>BetweenDrawings</name>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="229"/>
        <source>The first key has no lines to carry.</source>
        <translation>最初のキーには運ぶ線がありません。</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="122"/>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="231"/>
        <source>The second key has no lines to fit to.</source>
        <translation>二番目のキーには合わせる線がありません。</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="243"/>
        <source>The first key could not be meshed: %1</source>
        <translation>最初のキーをメッシュにできませんでした: %1</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="279"/>
        <source>The first key&apos;s lines are dots: there is nothing to fit.</source>
        <translation>最初のキーの線は点だけです。合わせるものがありません。</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="291"/>
        <source>The first key&apos;s mesh cannot be fitted: %1</source>
        <translation>最初のキーのメッシュを合わせられません: %1</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="89"/>
        <source>The lines of the first key around (%1, %2), %3 × %4 px, find nothing like them in the second key.</source>
        <translation>最初のキーの (%1, %2) 付近、%3 × %4 px の線に似たものが二番目のキーにありません。</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="98"/>
        <source>The first key&apos;s drawing cannot be laid on all of the second&apos;s: its lines around (%1, %2), %3 × %4 px (%5 % of them), have nothing of the first key on them. Draw a key between them, or draw the second closer to the first.</source>
        <translation>最初のキーの絵を二番目の絵全体に重ねられません。二番目の (%1, %2) 付近、%3 × %4 px の線（全体の %5 %）には最初のキーのどこも重なりません。間にキーを描くか、二番目を最初に近づけて描いてください。</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="110"/>
        <source>The two drawings are too different to fit one onto the other (%1 % of the drawing apart on the median, %2 % stretched).%3 Draw a key between them, or draw the second closer to the first.</source>
        <translation>二つの絵が違いすぎて、一方を他方に合わせられません (中央値で絵の %1 % 離れ、%2 % 伸びています)。%3 間にキーを描くか、二番目を最初に近づけて描いてください。</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="120"/>
        <source>A correspondence pin is not on the first key&apos;s drawing.</source>
        <translation>対応ピンが最初のキーの絵の上にありません。</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="124"/>
        <source>The fit could not be solved.</source>
        <translation>合わせ込みを解けませんでした。</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/between_drawings.cpp" line="139"/>
        <source>The fitted motion cannot be interpolated: %1</source>
        <translation>合わせた動きを補間できません: %1</translation>
    </message>
</context>
<context>
    <name>CelEditing</name>
    <message>
        <location filename="../ui/src/layers/cel_editing.cpp" line="113"/>
        <source>Cut Cels</source>
        <translation>セルを切り取り</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/cel_editing.cpp" line="141"/>
        <source>No cels have been copied.</source>
        <translation>コピーされたセルはありません。</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/cel_editing.cpp" line="149"/>
        <source>The cels cannot go onto a locked layer.</source>
        <translation>ロックされたレイヤーにはセルを置けません。</translation>
    </message>
</context>
<context>
    <name>Command</name>
    <message>
        <location filename="../model/src/commands.cpp" line="24"/>
        <source>Draw Stroke</source>
        <translation>ストロークを描画</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="48"/>
        <source>Erase Stroke</source>
        <translation>ストロークを消去</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="77"/>
        <source>Move Strokes to Object</source>
        <translation>ストロークをオブジェクトへ移動</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="172"/>
        <source>New Object</source>
        <translation>新規オブジェクト</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="200"/>
        <source>Delete Object</source>
        <translation>オブジェクトを削除</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="229"/>
        <source>Rename Object</source>
        <translation>オブジェクト名を変更</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="254"/>
        <source>Reorder Object</source>
        <translation>オブジェクトの順序を変更</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="285"/>
        <source>Show Object</source>
        <translation>オブジェクトを表示</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="285"/>
        <source>Hide Object</source>
        <translation>オブジェクトを非表示</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="287"/>
        <source>Lock Object</source>
        <translation>オブジェクトをロック</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="287"/>
        <source>Unlock Object</source>
        <translation>オブジェクトのロックを解除</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="321"/>
        <source>Insert Frame</source>
        <translation>フレームを挿入</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="325"/>
        <location filename="../model/src/scene/layer_commands.cpp" line="25"/>
        <source>Object</source>
        <translation>オブジェクト</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="346"/>
        <source>Duplicate Frame</source>
        <translation>フレームを複製</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="365"/>
        <location filename="../model/src/scene/layer_commands.cpp" line="413"/>
        <source>Paste Cels</source>
        <translation>セルを貼り付け</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="420"/>
        <source>Delete Frame</source>
        <translation>フレームを削除</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="447"/>
        <source>Move Frame</source>
        <translation>フレームを移動</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="471"/>
        <source>Change Frame Exposure</source>
        <translation>フレームの表示時間を変更</translation>
    </message>
    <message>
        <location filename="../model/src/commands.cpp" line="515"/>
        <source>Change Document Settings</source>
        <translation>ドキュメント設定を変更</translation>
    </message>
    <message>
        <location filename="../model/src/object_commands.cpp" line="28"/>
        <source>“%1” has lines under the picture of “%2”: one object draws its picture under its lines, so merged they would cover it. Put the picture below them first (Object → Send Backward).</source>
        <translation>「%1」には「%2」の画像の下に線があります。オブジェクトは画像を線の下に描くため、結合すると線が画像を覆ってしまいます。先に画像を下へ移してください（オブジェクト → 背面へ）。</translation>
    </message>
    <message>
        <location filename="../model/src/object_commands.cpp" line="43"/>
        <source>Merge Objects</source>
        <translation>オブジェクトを結合</translation>
    </message>
    <message>
        <location filename="../model/src/pins/pin_commands.cpp" line="56"/>
        <source>Add Pin</source>
        <translation>ピンを追加</translation>
    </message>
    <message>
        <location filename="../model/src/pins/pin_commands.cpp" line="64"/>
        <source>Remove Pin</source>
        <translation>ピンを削除</translation>
    </message>
    <message>
        <location filename="../model/src/pins/pin_commands.cpp" line="74"/>
        <source>Move Pin</source>
        <translation>ピンを移動</translation>
    </message>
    <message>
        <location filename="../model/src/pins/pin_commands.cpp" line="88"/>
        <source>Change Mesh Density</source>
        <translation>メッシュ密度を変更</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_commands.cpp" line="49"/>
        <source>Place Cage</source>
        <translation>ケージを配置</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_commands.cpp" line="56"/>
        <source>Edit Cage</source>
        <translation>ケージを編集</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_commands.cpp" line="67"/>
        <source>Move Cage Corners</source>
        <translation>ケージの頂点を移動</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_commands.cpp" line="75"/>
        <source>Remove Rig</source>
        <translation>リグを削除</translation>
    </message>
    <message>
        <location filename="../model/src/inbetween/inbetween_commands.cpp" line="17"/>
        <location filename="../model/src/inbetween/inbetween_commands.cpp" line="29"/>
        <source>Generate In-betweens</source>
        <translation>中割りを生成</translation>
    </message>
    <message>
        <location filename="../model/src/rig/rig_commands.cpp" line="92"/>
        <source>Reset Pose</source>
        <translation>ポーズをリセット</translation>
    </message>
    <message>
        <location filename="../model/src/rig/rig_commands.cpp" line="220"/>
        <location filename="../model/src/skeleton/skeleton_join_commands.cpp" line="199"/>
        <source>Apply Pose to Drawing</source>
        <translation>ポーズを絵に適用</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="78"/>
        <source>Build Skeleton</source>
        <translation>スケルトンを作成</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="89"/>
        <source>Change Skeleton Settings</source>
        <translation>スケルトンの設定を変更</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="117"/>
        <source>Pose Bones</source>
        <translation>ボーンのポーズを変更</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="126"/>
        <source>Change Skinning</source>
        <translation>スキニングを変更</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="143"/>
        <source>Lock Joint</source>
        <translation>関節をロック</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="143"/>
        <source>Unlock Joint</source>
        <translation>関節のロックを解除</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="170"/>
        <source>Reset Bone Pose</source>
        <translation>ボーンのポーズをリセット</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="182"/>
        <source>Move Joint</source>
        <translation>関節を移動</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="205"/>
        <source>Insert Joint</source>
        <translation>関節を挿入</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_commands.cpp" line="218"/>
        <source>Delete Joint</source>
        <translation>関節を削除</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_join_commands.cpp" line="106"/>
        <source>Join Part</source>
        <translation>パーツを接続</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_join_commands.cpp" line="130"/>
        <source>Detach Part</source>
        <translation>パーツを切り離す</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_join_commands.cpp" line="135"/>
        <source>Join Overlapping Parts</source>
        <translation>重なるパーツを接続</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_join_commands.cpp" line="166"/>
        <source>Make Character Root</source>
        <translation>キャラクターのルートにする</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_commands.cpp" line="92"/>
        <source>Recolour Fill</source>
        <translation>塗りの色を変更</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_commands.cpp" line="92"/>
        <source>Fill Region</source>
        <translation>領域を塗る</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_commands.cpp" line="101"/>
        <source>Remove Fill</source>
        <translation>塗りを削除</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_commands.cpp" line="112"/>
        <source>Fill All Enclosed Regions</source>
        <translation>閉じた領域をすべて塗る</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_commands.cpp" line="123"/>
        <source>Close Gaps</source>
        <translation>隙間を閉じる</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_commands.cpp" line="18"/>
        <source>Import Sound</source>
        <translation>サウンドのインポート</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_commands.cpp" line="37"/>
        <source>Delete Sound</source>
        <translation>サウンドの削除</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_commands.cpp" line="77"/>
        <source>Move Sound</source>
        <translation>サウンドの移動</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_commands.cpp" line="79"/>
        <source>Change Sound Volume</source>
        <translation>サウンドの音量変更</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_commands.cpp" line="83"/>
        <source>Mute Sound</source>
        <translation>サウンドをミュート</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_commands.cpp" line="83"/>
        <source>Unmute Sound</source>
        <translation>サウンドのミュート解除</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_commands.cpp" line="19"/>
        <source>Shade Fills</source>
        <translation>塗りに陰影を付ける</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_commands.cpp" line="19"/>
        <source>Unshade Fills</source>
        <translation>塗りの陰影を外す</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_commands.cpp" line="46"/>
        <source>Move Light</source>
        <translation>光源を動かす</translation>
    </message>
    <message>
        <location filename="../model/src/erase/stroke_cut.cpp" line="162"/>
        <source>Keep Fills Along a Cut</source>
        <translation>切断に沿って塗りを保持</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_commands.cpp" line="60"/>
        <source>Change Camera Key</source>
        <translation>カメラキーを変更</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_commands.cpp" line="60"/>
        <source>Add Camera Key</source>
        <translation>カメラキーを追加</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_commands.cpp" line="66"/>
        <source>Delete Camera Key</source>
        <translation>カメラキーを削除</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_commands.cpp" line="77"/>
        <source>Move Camera Key</source>
        <translation>カメラキーを移動</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="17"/>
        <source>New Layer</source>
        <translation>新しいレイヤー</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="47"/>
        <source>Duplicate Layer</source>
        <translation>レイヤーを複製</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="56"/>
        <source>%1 copy</source>
        <translation>%1 のコピー</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="77"/>
        <source>Delete Layer</source>
        <translation>レイヤーを削除</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="104"/>
        <source>Move Layer</source>
        <translation>レイヤーを移動</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="168"/>
        <source>Insert Time</source>
        <translation>時間を挿入</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="185"/>
        <source>Delete Time</source>
        <translation>時間を削除</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="222"/>
        <location filename="../model/src/scene/layer_commands.cpp" line="342"/>
        <source>Move Cels</source>
        <translation>セルを移動</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="252"/>
        <source>Insert Empty Cel</source>
        <translation>空のセルを挿入</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="342"/>
        <source>Copy Cels</source>
        <translation>セルをコピー</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_commands.cpp" line="430"/>
        <source>Delete Cels</source>
        <translation>セルを削除</translation>
    </message>
    <message>
        <location filename="../model/src/document.cpp" line="21"/>
        <location filename="../model/src/document.cpp" line="226"/>
        <location filename="../model/src/finbook_file_io.cpp" line="226"/>
        <source>Layer 1</source>
        <translation>レイヤー 1</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_keys.cpp" line="83"/>
        <source>The object is not swappable: make a mouth chart first (Object &gt; New Mouth Chart).</source>
        <translation>このオブジェクトは差し替えできません。先に口形チャートを作ってください（オブジェクト &gt; 新規口形チャート）。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_keys.cpp" line="89"/>
        <source>The set &quot;%1&quot; has no drawings named A to F (the mouth shapes lip sync keys): make a mouth chart, or name its drawings by their shapes.</source>
        <translation>セット「%1」には A〜F という名前の絵（リップシンクが使う口の形）がありません。口形チャートを作るか、絵に形の名前を付けてください。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_keys.cpp" line="96"/>
        <source>There is nothing to key.</source>
        <translation>キーを打つものがありません。</translation>
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
        <translation>X (休み)</translation>
    </message>
    <message>
        <location filename="../model/src/swap/mouth_chart.cpp" line="116"/>
        <source>Mouth</source>
        <translation>口</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="64"/>
        <source>Make Object Swappable</source>
        <translation>オブジェクトを差し替え可能にする</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="90"/>
        <source>New Swap Set</source>
        <translation>新しい差し替えセット</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="139"/>
        <source>Show Drawing &quot;%1&quot;</source>
        <translation>絵「%1」を表示</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="218"/>
        <source>New Drawing &quot;%1&quot;</source>
        <translation>新しい絵「%1」</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="270"/>
        <source>Rename Drawing</source>
        <translation>絵の名前を変更</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="300"/>
        <source>Delete Drawing &quot;%1&quot;</source>
        <translation>絵「%1」を削除</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_commands.cpp" line="334"/>
        <source>Make Drawing Independent</source>
        <translation>絵を独立させる</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_commands.cpp" line="18"/>
        <source>Import Picture</source>
        <translation>画像を読み込む</translation>
    </message>
    <message>
        <location filename="../model/src/fill/uncovered_lines.cpp" line="266"/>
        <source>Show Lines</source>
        <translation>線を表示</translation>
    </message>
</context>
<context>
    <name>CommandLine</name>
    <message>
        <location filename="../app/cli.cpp" line="193"/>
        <source>No command given; see finbook --help.</source>
        <translation>コマンドが指定されていません。finbook --help を参照してください。</translation>
    </message>
    <message>
        <location filename="../app/cli.cpp" line="197"/>
        <source>Usage: finbook info FILE</source>
        <translation>使い方: finbook info FILE</translation>
    </message>
    <message>
        <location filename="../app/cli.cpp" line="217"/>
        <source>Unknown command &quot;%1&quot;; see finbook --help.</source>
        <translation>不明なコマンド「%1」です。finbook --help を参照してください。</translation>
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
        <translation>Finbook: パラパラ漫画のアニメーションエディター。

  finbook [FILE]               FILE をエディターで開く
  finbook info FILE            FILE の概要を JSON で出力する
  finbook export FILE OUTDIR   すべてのフレームを OUTDIR/frame_0001.png ... に描き出す
  finbook export FILE OUT      OUT.gif、.mp4、.webm、.apng、.html に書き出す
  finbook export FILE OUT.obj --frame N   フレーム N を 3D モデル (OUT.obj、OUT.mtl) に書き出す
  finbook export FILE OUT.glb --frame N   フレーム N を 3D モデル (glTF バイナリ) に書き出す
  finbook export FILE... --format F --out-dir DIR   複数のファイルを書き出す
  finbook thumbnail FILE OUT.png SIZE   最初のフレームを最大 SIZE px の PNG に書き出す</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="56"/>
        <source>Use LANGUAGE (e.g. de, en, fr, ja) instead of the system&apos;s.</source>
        <translation>システムの言語の代わりに LANGUAGE（例: de, en, fr, ja）を使う。</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="62"/>
        <source>FILE, or a command.</source>
        <translation>FILE、またはコマンド。</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="74"/>
        <source>see finbook --help</source>
        <comment>after an error</comment>
        <translation>finbook --help を参照してください</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="81"/>
        <source>%1; %2.</source>
        <comment>an argument error from Qt, then &quot;see finbook --help&quot;</comment>
        <translation>%1。%2。</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="117"/>
        <source>Unknown command &quot;%1&quot;; %2.</source>
        <translation>不明なコマンド「%1」です。%2。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="43"/>
        <source>export: frames A to B (default: the play range).</source>
        <translation>export: フレーム A～B（既定: 再生範囲）。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="39"/>
        <source>export: png, svg, gif, mp4, webm, apng, html, obj, glb, json (Lottie) or lottie (dotLottie).</source>
        <translation>export: png、svg、gif、mp4、webm、apng、html、obj、glb、json (Lottie)、lottie (dotLottie) のいずれか。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="45"/>
        <source>export: frame N only; a 3D model (obj, glb) is one frame, by default the first of the play range.</source>
        <translation>export: フレーム N のみ。3D モデル (obj、glb) は 1 フレームで、既定では再生範囲の最初のフレーム。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="48"/>
        <source>export: multiply the canvas size by S.</source>
        <translation>export: キャンバスサイズを S 倍にする。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="50"/>
        <source>export: N frames per second (default: the document&apos;s).</source>
        <translation>export: 毎秒 N フレーム（既定: ドキュメントの設定）。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="52"/>
        <source>export: this background colour (#rrggbb).</source>
        <translation>export: この背景色（#rrggbb）を使う。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="53"/>
        <source>export: no background.</source>
        <translation>export: 背景なし。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="55"/>
        <source>export png/svg: one file per drawing plus an exposure sheet.</source>
        <translation>export png/svg: 絵ごとに 1 ファイルとタイムシートを書き出す。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="58"/>
        <source>export: paint the document&apos;s reference picture or video under the drawing.</source>
        <translation>export: 文書の参照画像または参照動画を絵の下に描きます。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="62"/>
        <source>export: the whole page, not the shot the document&apos;s camera frames.</source>
        <translation>export: 文書のカメラが写すショットではなく、ページ全体。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="65"/>
        <source>export: only the layers named A, B, ... (hidden ones too), not every visible layer.</source>
        <translation>export: すべての表示レイヤーではなく、A, B, ... という名前のレイヤーだけ（非表示のものも含む）。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="69"/>
        <source>export: fail (exit code 2, nothing written) when a sound clip or the reference cannot be used, instead of leaving it out with a warning.</source>
        <translation>export: サウンドクリップまたは参照画像を使用できないとき、警告して省く代わりに失敗します（終了コード 2、何も書き出しません）。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="72"/>
        <source>export: replace existing files.</source>
        <translation>export: 既存のファイルを置き換える。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="73"/>
        <source>export: write each FILE into DIR.</source>
        <translation>export: 各 FILE を DIR に書き出す。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="75"/>
        <source>export: allow up to N frames (default: 100000 files, 3 hours of video).</source>
        <translation>export: 最大 N フレームまで許可します（既定: 100000 ファイル、動画 3 時間）。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="107"/>
        <source>--range needs A-B with 1 &lt;= A &lt;= B, not &quot;%1&quot;.</source>
        <translation>--range には「%1」ではなく、1 &lt;= A &lt;= B を満たす A-B を指定してください。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="121"/>
        <source>--frame and --range cannot be used together.</source>
        <translation>--frame と --range は同時に使えません。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="124"/>
        <source>--frame needs a frame number from 1, not &quot;%1&quot;.</source>
        <translation>--frame には 1 以上のフレーム番号を指定してください (「%1」ではなく)。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="131"/>
        <source>--scale needs a number above 0, not &quot;%1&quot;.</source>
        <translation>--scale には「%1」ではなく、0 より大きい数値を指定してください。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="137"/>
        <source>--fps needs a whole number from %1 to %2, not &quot;%3&quot;.</source>
        <translation>--fps には「%3」ではなく、%1～%2 の整数を指定してください。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="145"/>
        <source>--max-frames needs a whole number above 0, not &quot;%1&quot;.</source>
        <translation>--max-frames には 0 より大きい整数を指定してください（「%1」ではなく）。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="151"/>
        <source>--background needs a colour such as #ffffff, not &quot;%1&quot;.</source>
        <translation>--background には「%1」ではなく、#ffffff のような色を指定してください。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="163"/>
        <source>Unknown export format &quot;%1&quot;; use png, svg, gif, mp4, webm, apng, html, obj, glb, json (Lottie) or lottie (dotLottie).</source>
        <translation>不明な書き出し形式「%1」です。png、svg、gif、mp4、webm、apng、html、obj、glb、json (Lottie)、lottie (dotLottie) のいずれかを使ってください。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="186"/>
        <source>Cannot tell the format from &quot;%1&quot;: end it in .gif, .mp4, .webm, .apng, .html, .obj, .glb, .json (Lottie) or .lottie, give a folder for PNG frames, or use --format.</source>
        <translation>「%1」から形式を判断できません。末尾を .gif、.mp4、.webm、.apng、.html、.obj、.glb、.json (Lottie)、.lottie にするか、PNG フレーム用のフォルダーを指定するか、--format を使ってください。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="179"/>
        <source>&quot;%1&quot; is a folder, not a %2 file; give a file name, or --format png to write PNG frames into the folder.</source>
        <translation>「%1」は %2 ファイルではなくフォルダーです。ファイル名を指定するか、フォルダーに PNG フレームを書き出すには --format png を指定してください。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="191"/>
        <source>--format %1 does not match &quot;%2&quot;.</source>
        <translation>--format %1 が「%2」と一致しません。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="207"/>
        <source>Usage: finbook export FILE OUT, or finbook export FILE... --out-dir DIR</source>
        <translation>使い方: finbook export FILE OUT、または finbook export FILE... --out-dir DIR</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="211"/>
        <source>Usage: finbook export FILE... --out-dir DIR</source>
        <translation>使い方: finbook export FILE... --out-dir DIR</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="228"/>
        <source>--layers needs the names of layers, separated by commas.</source>
        <translation>--layers にはカンマで区切ったレイヤー名が必要です。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="231"/>
        <source>--transparent and --background cannot be used together.</source>
        <translation>--transparent と --background は同時に使えません。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="233"/>
        <source>--one-per-drawing is for png and svg exports only.</source>
        <translation>--one-per-drawing は png と svg の書き出しでのみ使えます。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="329"/>
        <source>Could not write &quot;%1&quot;: %2. Nothing was exported.</source>
        <translation>「%1」を書き込めませんでした: %2。何も書き出されていません。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="344"/>
        <source>&quot;%1&quot; has no layer named &quot;%2&quot;; its layers are %3. Nothing was exported.</source>
        <translation>「%1」には「%2」という名前のレイヤーがありません。レイヤーは %3 です。何も書き出されませんでした。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="360"/>
        <source>Interrupted; nothing was exported.</source>
        <translation>中断されました。何も書き出されていません。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="368"/>
        <source>Use --overwrite to replace it.</source>
        <translation>置き換えるには --overwrite を使ってください。</translation>
    </message>
    <message>
        <location filename="../app/cli_export.cpp" line="370"/>
        <source>Use --max-frames N to allow N frames.</source>
        <translation>N フレームまで許可するには --max-frames N を使ってください。</translation>
    </message>
</context>
<context>
    <name>Deformation</name>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="127"/>
        <source>The object has no strokes to deform.</source>
        <translation>このオブジェクトには変形できるストロークがありません。</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="134"/>
        <source>This drawing cannot be meshed for deformation: %1</source>
        <translation>この絵から変形用のメッシュを作成できません: %1</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="166"/>
        <source>Cancelled.</source>
        <translation>キャンセルしました。</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="217"/>
        <source>The cage changed while it was being prepared.</source>
        <translation>準備中にケージが変更されました。</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="225"/>
        <source>The object has no mesh to deform.</source>
        <translation>このオブジェクトには変形できるメッシュがありません。</translation>
    </message>
    <message>
        <location filename="../model/src/pins/pin_setup.cpp" line="20"/>
        <source>The pins cannot be solved on this drawing: %1</source>
        <translation>この絵ではピンによる変形を計算できません: %1</translation>
    </message>
    <message>
        <location filename="../model/src/pins/pin_setup.cpp" line="49"/>
        <source>The pins could not be solved: %1</source>
        <translation>ピンによる変形を計算できませんでした: %1</translation>
    </message>
    <message>
        <location filename="../model/src/deform_setup.cpp" line="248"/>
        <source>The deformation produced invalid points; it was not applied.</source>
        <translation>変形によって無効な点が生じたため、適用しませんでした。</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_setup.cpp" line="35"/>
        <source>The cage cannot be used: %1</source>
        <translation>ケージを使用できません: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/cage/cage_setup.cpp" line="41"/>
        <source>%n stroke point(s) lie outside the cage; move its corners out so it encloses the drawing.</source>
        <translation>
            <numerusform>%n 個のストロークの点がケージの外にあります。絵を囲むように、ケージの頂点を外側へ動かしてください。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_setup.cpp" line="44"/>
        <source>The drawing cannot be bound to the cage: %1</source>
        <translation>この絵をケージにバインドできません: %1</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_setup.cpp" line="59"/>
        <location filename="../model/src/cage/cage_setup.cpp" line="62"/>
        <source>The cage could not be solved: %1</source>
        <translation>ケージによる変形を計算できませんでした: %1</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_setup.cpp" line="72"/>
        <source>This cage cannot be used: %1</source>
        <translation>このケージは使用できません: %1</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_setup.cpp" line="76"/>
        <source>The cage must enclose the whole object: %1</source>
        <translation>ケージはオブジェクト全体を囲む必要があります: %1</translation>
    </message>
    <message>
        <location filename="../model/src/cage/cage_setup.cpp" line="99"/>
        <source>No cage fits this drawing: %1</source>
        <translation>この絵に合うケージがありません: %1</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_build.cpp" line="42"/>
        <source>No skeleton can be built for this drawing: %1</source>
        <translation>この絵にはスケルトンを作成できません: %1</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_build.cpp" line="55"/>
        <source>The object has no strokes to build a skeleton in.</source>
        <translation>このオブジェクトにはスケルトンを作成するためのストロークがありません。</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_build.cpp" line="73"/>
        <location filename="../model/src/skeleton/skeleton_build.cpp" line="88"/>
        <source>No skeleton can be built for this drawing.</source>
        <translation>この絵にはスケルトンを作成できません。</translation>
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
        <translation>スケルトンが破損しています。作成し直してください。</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="29"/>
        <source>Reset the pose or apply it to the drawing before editing joints.</source>
        <translation>関節を編集する前に、ポーズをリセットするか絵に適用してください。</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="31"/>
        <source>There is no such joint.</source>
        <translation>その関節はありません。</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="50"/>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="64"/>
        <source>A joint cannot go there.</source>
        <translation>そこには関節を置けません。</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="62"/>
        <source>A joint can only be inserted on a bone.</source>
        <translation>関節はボーンの上にだけ挿入できます。</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="69"/>
        <source>The bone is too short to split.</source>
        <translation>ボーンが短すぎて分割できません。</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_joint_edit.cpp" line="102"/>
        <source>A skeleton needs at least one bone.</source>
        <translation>スケルトンには少なくとも 1 本のボーンが必要です。</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="34"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="57"/>
        <source>The skeleton cannot be used: %1</source>
        <translation>スケルトンを使用できません: %1</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="123"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="138"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="168"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="178"/>
        <source>The skeleton cannot skin this drawing: %1</source>
        <translation>このスケルトンではこの絵をスキニングできません: %1</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="73"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="295"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="299"/>
        <location filename="../model/src/skeleton/skeleton_setup.cpp" line="305"/>
        <source>The bones could not be posed: %1</source>
        <translation>ボーンのポーズを計算できませんでした: %1</translation>
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
        <translation>描画に必要なメモリが足りません</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="53"/>
        <source>its folder cannot be created</source>
        <translation>フォルダーを作成できません</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_encoded.cpp" line="169"/>
        <source>ffmpeg finished without writing the %1; nothing was exported.</source>
        <translation>ffmpeg は %1 を書き出さずに終了しました。何も書き出されていません。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_flipbook.cpp" line="168"/>
        <source>Flipbook</source>
        <translation>パラパラ漫画</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_flipbook.cpp" line="180"/>
        <location filename="../model/src/export/export_flipbook.cpp" line="191"/>
        <source>Play</source>
        <translation>再生</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_flipbook.cpp" line="182"/>
        <source>Loop</source>
        <translation>ループ</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_flipbook.cpp" line="185"/>
        <source>Frame</source>
        <translation>フレーム</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_flipbook.cpp" line="192"/>
        <source>Pause</source>
        <translation>一時停止</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="46"/>
        <source>The frame range %1-%2 is not within the animation&apos;s frames 1-%3; choose a range inside it.</source>
        <translation>フレーム範囲 %1～%2 がアニメーションのフレーム 1～%3 に収まっていません。その範囲内で選んでください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="80"/>
        <source>The camera moves while a drawing is held, so one file per drawing cannot show the shot; export one file per frame, or without the camera.</source>
        <translation>絵を保持している間にカメラが動くため、絵ごとに 1 ファイルではショットを表せません。フレームごとに 1 ファイルで書き出すか、カメラなしで書き出してください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="116"/>
        <source>The animation has no frames to export.</source>
        <translation>アニメーションに書き出すフレームがありません。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="118"/>
        <source>The canvas has no size; set one in Document Settings.</source>
        <translation>キャンバスのサイズがありません。ドキュメント設定で設定してください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="126"/>
        <source>A 3D model holds one frame, not the frames %1-%2; choose a single frame.</source>
        <translation>3D モデルに入るのは 1 フレームだけで、フレーム %1-%2 は入りません。フレームを 1 つ選んでください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="146"/>
        <source>The scale %1 is not a size a picture can have; choose a scale that gives 1 to %2 pixels a side.</source>
        <translation>倍率 %1 は画像のサイズとして使えません。一辺が 1～%2 ピクセルになる倍率を選んでください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="150"/>
        <source>The scale %1 would make a %2 x %3 pixel picture; choose a scale that gives 1 to %4 pixels a side.</source>
        <translation>倍率 %1 では %2×%3 ピクセルの画像になります。一辺が 1～%4 ピクセルになる倍率を選んでください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="163"/>
        <source>The frame rate %1 is not possible; choose %2 to %3 frames per second.</source>
        <translation>フレームレート %1 は使用できません。毎秒 %2～%3 フレームの範囲で選んでください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="171"/>
        <source>%1 video cannot be transparent; choose WebM, APNG, GIF or PNG for a transparent background.</source>
        <translation>%1 動画は透明にできません。背景を透明にするには WebM、APNG、GIF、PNG のいずれかを選んでください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="199"/>
        <source>This export would write %1 frames, more than the %2 allowed; nothing was exported.</source>
        <translation>この書き出しは %1 フレームを書き込みます。許可された %2 を超えるため、何も書き出していません。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="206"/>
        <source>This export would write %1 files (%2 playback ticks), more than %3 without your explicit permission; nothing was exported.</source>
        <translation>この書き出しは %1 個のファイル（再生ティック %2）を書き込みます。明示的な許可なしに %3 を超えることはできないため、何も書き出していません。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_plan.cpp" line="214"/>
        <source>This export would make %1 hours of animation (%2 frames), more than %3 hours without your explicit permission; nothing was exported.</source>
        <translation>この書き出しは %1 時間のアニメーション（%2 フレーム）になります。明示的な許可なしに %3 時間を超えることはできないため、何も書き出していません。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_sequence.cpp" line="68"/>
        <source>&quot;%1&quot; is a folder where a file should go; choose another folder.</source>
        <translation>「%1」はファイルを置く場所にあるフォルダーです。別のフォルダーを選んでください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_sequence.cpp" line="119"/>
        <source>&quot;%1&quot; is a file, not a folder; choose a folder for the %2 files, or remove the file.</source>
        <translation>「%1」はフォルダーではなくファイルです。%2 ファイル用のフォルダーを選ぶか、そのファイルを削除してください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_sequence.cpp" line="128"/>
        <source>&quot;%1&quot; is the top folder of the disk; choose or name a folder for the frames, such as &quot;%2&quot;.</source>
        <translation>「%1」はディスクの最上位フォルダーです。「%2」のように、フレーム用のフォルダーを選ぶか名前を付けてください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_sequence.cpp" line="137"/>
        <source>the folder cannot be created</source>
        <translation>フォルダーを作成できません</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="23"/>
        <source>&quot;%1&quot; already exists; nothing was exported.</source>
        <translation>「%1」はすでに存在するため、何も書き出しませんでした。</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="30"/>
        <source>Could not write &quot;%1&quot;: %2. Nothing was exported; free some disk space or choose another folder, then export again.</source>
        <translation>「%1」を書き込めませんでした: %2。何も書き出されていません。ディスクの空き容量を増やすか別のフォルダーを選んでから、もう一度書き出してください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="38"/>
        <source>The export was cancelled; nothing was written.</source>
        <translation>書き出しはキャンセルされました。何も書き込まれていません。</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="44"/>
        <source>Another export is writing to &quot;%1&quot;; wait until it has finished, or choose another target.</source>
        <translation>別の書き出しが「%1」に書き込み中です。終わるまで待つか、別の書き出し先を選んでください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="113"/>
        <source>&quot;%1&quot; is a folder; give a file name ending in .%2.</source>
        <translation>「%1」はフォルダーです。末尾が .%2 のファイル名を指定してください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="254"/>
        <source>Choose where to export the animation to.</source>
        <translation>アニメーションの書き出し先を選んでください。</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/export/exporter.cpp" line="268"/>
        <source>%n more sound clip(s) are left out too.</source>
        <translation>
            <numerusform>ほかに %n 個のサウンドクリップも省かれます。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/export/exporter.cpp" line="275"/>
        <source>Nothing was exported.</source>
        <translation>何も書き出されませんでした。</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_arguments.cpp" line="41"/>
        <source>GIF</source>
        <translation>GIF</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_arguments.cpp" line="70"/>
        <source>MP4 video</source>
        <translation>MP4 動画</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_arguments.cpp" line="88"/>
        <source>WebM video</source>
        <translation>WebM 動画</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_arguments.cpp" line="102"/>
        <source>animated PNG</source>
        <translation>アニメーション PNG</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_encoder.cpp" line="175"/>
        <source>Exporting %1 needs the ffmpeg program, which was not found; install it (on Debian: apt install ffmpeg) and export again.</source>
        <translation>%1 を書き出すには ffmpeg プログラムが必要ですが、見つかりませんでした。インストールしてから（Debian の場合: apt install ffmpeg）、もう一度書き出してください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_encoder.cpp" line="268"/>
        <source>it stopped unexpectedly</source>
        <translation>予期せず停止しました</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_encoder.cpp" line="269"/>
        <source>exit code %1</source>
        <translation>終了コード %1</translation>
    </message>
    <message>
        <location filename="../model/src/export/ffmpeg_encoder.cpp" line="272"/>
        <source>ffmpeg could not make the %1 (%2); nothing was written. If the disk is full, free some space and export again.</source>
        <translation>ffmpeg で %1 を作成できませんでした（%2）。何も書き込まれていません。ディスクがいっぱいの場合は、空き容量を増やしてからもう一度書き出してください。</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/export/ffmpeg_encoder.cpp" line="283"/>
        <source>ffmpeg made no progress for %n second(s) and was stopped; nothing was written. Check that ffmpeg works, then export again.</source>
        <translation>
            <numerusform>ffmpeg が %n 秒間進まなかったため停止しました。何も書き込まれていません。ffmpeg が動作するか確認してから、もう一度書き出してください。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/export/pending_output.cpp" line="341"/>
        <source>a folder cannot be created in it</source>
        <translation>その中にフォルダーを作成できません</translation>
    </message>
    <message>
        <location filename="../model/src/export/pending_output.cpp" line="362"/>
        <source>&quot;%1&quot; is a folder where a file should go</source>
        <translation>ファイルを置くべき場所に「%1」というフォルダーがあります</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_model.cpp" line="68"/>
        <source>The 3D model of frame %1 would have more than %L2 vertices, the most a 3D export writes (about 25 MB of glTF). Nothing was exported; lower the mesh density of its objects (Deform → Mesh Density) or hide some of them.</source>
        <translation>フレーム %1 の 3D モデルは頂点が %L2 個を超えます。これは 3D 書き出しの上限です（glTF で約 25 MB）。何も書き出していません。オブジェクトのメッシュ密度を下げる（変形 → メッシュ密度）か、いくつか非表示にしてください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_model.cpp" line="79"/>
        <source>Frame %1 shows no drawing to make a 3D model of; choose another frame.</source>
        <translation>フレーム %1 には 3D モデルにできる絵がありません。別のフレームを選んでください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_model.cpp" line="84"/>
        <source>No object of frame %1 can be made 3D: their points lie more than %L2 pixels from the page, too far out to mesh. Nothing was exported; move the drawing back onto the page or choose another frame.</source>
        <translation>フレーム %1 のオブジェクトはどれも 3D にできません。点がページから %L2 ピクセル以上離れていて、メッシュにできません。何も書き出していません。絵をページに戻すか、別のフレームを選んでください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_model.cpp" line="92"/>
        <source>No object of frame %1 can be made 3D: each is a dot or a straight line, with no area to inflate, or lies too far from the page to mesh. Nothing was exported; draw a shape or choose another frame.</source>
        <translation>フレーム %1 のオブジェクトはどれも 3D にできません。どれも点か直線で膨らませる面がないか、ページから遠すぎてメッシュにできません。何も書き出していません。形を描くか、別のフレームを選んでください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_model.cpp" line="99"/>
        <source>No object of frame %1 can be made 3D: each is a dot or a straight line, with no area to inflate. Nothing was exported; draw a shape or choose another frame.</source>
        <translation>フレーム %1 のオブジェクトはどれも 3D にできません。どれも点か直線で、膨らませる面がありません。何も書き出していません。形を描くか、別のフレームを選んでください。</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/export/export_model.cpp" line="110"/>
        <source>%n object(s) of frame %1 could not be made 3D (a dot or a straight line has no area to inflate; a drawing far off the page cannot be meshed) and were left out.</source>
        <translation>
            <numerusform>フレーム %1 のオブジェクト %n 個は 3D にできず（点や直線には膨らませる面がなく、ページから遠く離れた絵はメッシュにできません）、省きました。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/export/export_obj.cpp" line="187"/>
        <source>&quot;%1&quot; would be overwritten by its own material file; give a file name ending in .obj.</source>
        <translation>「%1」は自身のマテリアルファイルで上書きされてしまいます。末尾が .obj のファイル名を指定してください。</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/export/export_model.cpp" line="115"/>
        <source>%n object(s) of frame %1 could not be made 3D (a dot or a straight line has no area to inflate) and were left out.</source>
        <translation>
            <numerusform>フレーム %1 の %n 個のオブジェクトは 3D にできなかったため (点や直線には膨らませる面がありません)、省きました。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/export/export_glb.cpp" line="48"/>
        <source>Frame %1 makes a 3D model larger than a glTF file can hold (4 GiB); export it as OBJ instead.</source>
        <translation>フレーム %1 の 3D モデルは glTF ファイルに収まる大きさ (4 GiB) を超えます。代わりに OBJ で書き出してください。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_sound.cpp" line="76"/>
        <source>The sound &quot;%1&quot; is left out: %2</source>
        <translation>サウンド「%1」は省かれます: %2</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_export.cpp" line="18"/>
        <source>The reference &quot;%1&quot; is left out: %2</source>
        <translation>参照「%1」は省かれます: %2</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_lottie.cpp" line="759"/>
        <source>the zip container failed</source>
        <translation>ZIP コンテナーを書き込めませんでした</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_lottie.cpp" line="775"/>
        <source>Lottie has no place for the reference picture; it is left out.</source>
        <translation>Lottie には参照画像を入れられないため、省きました。</translation>
    </message>
    <message>
        <location filename="../model/src/export/export_lottie.cpp" line="777"/>
        <source>Lottie carries no sound; the soundtrack is left out.</source>
        <translation>Lottie は音声を持てないため、サウンドトラックは省きました。</translation>
    </message>
</context>
<context>
    <name>ExportDone</name>
    <message>
        <location filename="../ui/src/export/export_done.cpp" line="26"/>
        <source>Export Finished</source>
        <translation>書き出し完了</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_done.cpp" line="31"/>
        <source>Show in Folder</source>
        <translation>フォルダーで表示</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_done.cpp" line="38"/>
        <source>Open in Browser</source>
        <translation>ブラウザーで開く</translation>
    </message>
</context>
<context>
    <name>FileMessages</name>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="17"/>
        <source>The file is not there any more: it may have been moved, renamed or deleted.</source>
        <translation>ファイルがもうありません。移動、名前の変更、または削除された可能性があります。</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="21"/>
        <source>This is a folder, not an animation. Choose a file ending in .finbook.</source>
        <translation>これはアニメーションではなくフォルダーです。末尾が .finbook のファイルを選んでください。</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="23"/>
        <source>This is a device or a pipe, not an animation. Choose a file ending in .finbook.</source>
        <translation>これはアニメーションではなく、デバイスまたはパイプです。末尾が .finbook のファイルを選んでください。</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="26"/>
        <source>You are not allowed to read this file. Ask whoever owns it to share it with you, or open a copy of it.</source>
        <translation>このファイルを読み取る権限がありません。所有者に共有を依頼するか、ファイルのコピーを開いてください。</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="29"/>
        <source>The disk could not read the file. If it is on a removable drive or a network folder, check that it is still connected.</source>
        <translation>ディスクからファイルを読み取れませんでした。リムーバブルドライブやネットワークフォルダー上にある場合は、まだ接続されているか確認してください。</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="33"/>
        <source>The file is empty: there is no drawing in it.</source>
        <translation>ファイルが空です。絵が何も入っていません。</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="34"/>
        <source>This is not a Finbook animation. Choose a file ending in .finbook.</source>
        <translation>これは Finbook のアニメーションではありません。末尾が .finbook のファイルを選んでください。</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="37"/>
        <source>It was saved by a newer version of Finbook. Install that version to open it.</source>
        <translation>より新しいバージョンの Finbook で保存されています。開くにはそのバージョンをインストールしてください。</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="40"/>
        <source>The file is damaged near the end: it looks cut off. Perhaps a copy or a save was interrupted.</source>
        <translation>ファイルの末尾付近が破損しています。途中で切れているようです。コピーや保存が中断された可能性があります。</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="43"/>
        <source>The file is damaged, or too large for this computer: it asks for more memory than Finbook can use.</source>
        <translation>ファイルが破損しているか、このコンピューターには大きすぎます。Finbook が使用できる以上のメモリを必要としています。</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="46"/>
        <source>The file is damaged: some of it changed after it was saved. Finbook can open what is still readable.</source>
        <translation>ファイルが破損しています。保存後に一部が変更されています。Finbook は、まだ読み取れる部分を開くことができます。</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="50"/>
        <source>This computer has not enough free memory to open the file. Close other programs or documents and try again.</source>
        <translation>このコンピューターには、ファイルを開くのに十分な空きメモリがありません。ほかのプログラムやドキュメントを閉じてから、もう一度お試しください。</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="57"/>
        <source>The file is damaged: part of it cannot be read.</source>
        <translation>ファイルが破損しています。一部を読み取れません。</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="64"/>
        <source>Finbook cannot open “%1”.</source>
        <translation>Finbook は「%1」を開けません。</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/file_messages.cpp" line="68"/>
        <source>Finbook kept the version saved before it as “%1” in the same folder: open that one to get your work back.</source>
        <translation>Finbook は、その前に保存されていたバージョンを同じフォルダーに「%1」として残しています。作業内容を取り戻すには、そちらを開いてください。</translation>
    </message>
</context>
<context>
    <name>FinbookFile</name>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="30"/>
        <source>layer %1</source>
        <translation>レイヤー %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="32"/>
        <source>frame %1</source>
        <translation>フレーム %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="35"/>
        <source>, object &quot;%1&quot;</source>
        <translation>、オブジェクト「%1」</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="36"/>
        <source>, object %1</source>
        <translation>、オブジェクト %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="38"/>
        <source>, stroke %1</source>
        <translation>、ストローク %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="42"/>
        <source>stroke data %1</source>
        <translation>ストロークデータ %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="44"/>
        <source>pose %1</source>
        <translation>ポーズ %1</translation>
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
        <translation>%1 がレコードの終わりを超えています（%2 バイト必要、残り %3 バイト）。ファイル内の長さの値が誤っています</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="100"/>
        <source>the file ends inside %1 (%2 bytes needed, %3 left)</source>
        <translation>%1 の途中でファイルが終わっています（%2 バイト必要ですが、残りは %3 バイトです）</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="116"/>
        <source>%1 claims %2 entries but only %3 bytes remain</source>
        <translation>%1 には %2 個の項目があるはずですが、残りは %3 バイトしかありません</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_cursor.h" line="142"/>
        <source>%1 has %2 unexpected bytes at its end</source>
        <translation>%1 の末尾に予期しない %2 バイトがあります</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="36"/>
        <source>%1 The file is incomplete (perhaps an interrupted copy or save); if there is a backup with the same name ending in ~, open that instead.</source>
        <translation>%1 ファイルが不完全です（コピーや保存が中断された可能性があります）。同じ名前で末尾に ~ が付いたバックアップがあれば、代わりにそちらを開いてください。</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="42"/>
        <source>%1 The file is damaged; if there is a backup with the same name ending in ~, open that instead.</source>
        <translation>%1 ファイルが破損しています。同じ名前で末尾に ~ が付いたバックアップがあれば、代わりにそちらを開いてください。</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="47"/>
        <source>%1 The file is damaged; Finbook can open what is still readable of it, or open the backup with the same name ending in ~ if there is one.</source>
        <translation>%1 ファイルが破損しています。Finbook でまだ読み取れる部分を開くか、同じ名前で末尾に ~ が付いたバックアップがあれば、そちらを開いてください。</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="52"/>
        <source>%1 Close other programs or documents and try again.</source>
        <translation>%1 ほかのプログラムやドキュメントを閉じてから、もう一度お試しください。</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="75"/>
        <source>Could not save &quot;%1&quot;: %2. The previous file is unchanged; free some disk space or choose another folder, then save again.</source>
        <translation>「%1」を保存できませんでした: %2。以前のファイルは変更されていません。ディスクの空き容量を増やすか別のフォルダーを選んでから、もう一度保存してください。</translation>
    </message>
    <message>
        <location filename="../model/src/io/atomic_file.cpp" line="249"/>
        <source>the backup &quot;%1&quot; cannot be written (%2)</source>
        <translation>バックアップ「%1」を書き込めません（%2）</translation>
    </message>
    <message>
        <location filename="../model/src/io/atomic_file.cpp" line="350"/>
        <source>the disk is full</source>
        <translation>ディスクがいっぱいです</translation>
    </message>
    <message>
        <location filename="../model/src/io/atomic_file.cpp" line="352"/>
        <source>the disk is read-only</source>
        <translation>ディスクが読み取り専用です</translation>
    </message>
    <message>
        <location filename="../model/src/io/atomic_file.cpp" line="354"/>
        <source>you do not have permission to write in the folder &quot;%1&quot;</source>
        <translation>フォルダー「%1」に書き込む権限がありません</translation>
    </message>
    <message>
        <location filename="../model/src/io/atomic_file.cpp" line="357"/>
        <source>the folder &quot;%1&quot; does not exist</source>
        <translation>フォルダー「%1」が存在しません</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="81"/>
        <source>Could not save &quot;%1&quot;: %2. The previous file is unchanged; choose another folder, then save again.</source>
        <translation>「%1」を保存できませんでした: %2。以前のファイルは変更されていません。別のフォルダーを選んでから、もう一度保存してください。</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="91"/>
        <source>Cannot open &quot;%1&quot;: %2. Check that the file exists and that you may read it.</source>
        <translation>「%1」を開けません: %2。ファイルが存在し、読み取る権限があることを確認してください。</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="132"/>
        <source>it is a folder</source>
        <translation>フォルダーです</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="165"/>
        <source>Cannot read &quot;%1&quot;: %2.</source>
        <translation>「%1」を読み込めません: %2。</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="146"/>
        <location filename="../model/src/finbook_file_io.cpp" line="176"/>
        <source>Cannot open &quot;%1&quot;. %2</source>
        <translation>「%1」を開けません。%2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="136"/>
        <source>Cannot open &quot;%1&quot;: it is a device, a pipe or a socket, not a file. Choose a .finbook file.</source>
        <translation>「%1」を開けません: ファイルではなく、デバイス、パイプ、またはソケットです。.finbook ファイルを選んでください。</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="155"/>
        <source>Cannot open &quot;%1&quot;: there is not enough memory for its %2 MB. Close other programs or documents and try again.</source>
        <translation>「%1」を開けません: %2 MB を読み込むのに十分なメモリがありません。ほかのプログラムやドキュメントを閉じてから、もう一度お試しください。</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_io.cpp" line="266"/>
        <source>Could not save &quot;%1&quot;: the drawing holds invalid data (%2). The previous file is unchanged.</source>
        <translation>「%1」を保存できませんでした: 絵に無効なデータが含まれています（%2）。以前のファイルは変更されていません。</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="44"/>
        <source>unknown %1 %2</source>
        <translation>不明な%1 %2</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="47"/>
        <source>it holds data (&quot;%1&quot;) that this version of Finbook does not know, so it was probably made by a newer Finbook; please update Finbook to open it</source>
        <translation>このバージョンの Finbook が知らないデータ（「%1」）が含まれているため、より新しい Finbook で作成されたと思われます。開くには Finbook を更新してください</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="67"/>
        <source>more problems were found and repaired the same way</source>
        <translation>ほかにも問題が見つかり、同じ方法で修復しました</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="76"/>
        <source>it describes more than a file of its size can hold (opening it would take more than %1 MB of memory)</source>
        <translation>このサイズのファイルに収まる量を超える内容が記述されています（開くには %1 MB を超えるメモリが必要です）</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="45"/>
        <source>its format version %1 is not one any Finbook writes (this version reads %2 to %3), so the version number is damaged</source>
        <translation>形式バージョン %1 はどの Finbook も書き出さないものです（このバージョンが読めるのは %2 から %3）。バージョン番号が破損しています</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="55"/>
        <source>the file is empty</source>
        <translation>ファイルが空です</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="57"/>
        <source>the file header</source>
        <translation>ファイルヘッダー</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="59"/>
        <source>it is not a Finbook animation</source>
        <translation>Finbook のアニメーションではありません</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="61"/>
        <source>the file ends inside its header</source>
        <translation>ヘッダーの途中でファイルが終わっています</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="62"/>
        <source>the format version</source>
        <translation>フォーマットのバージョン</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_header.cpp" line="67"/>
        <source>it was made by a newer version of Finbook (file format %1; this version reads up to %2); please update Finbook to open it</source>
        <translation>より新しいバージョンの Finbook で作成されています（ファイル形式 %1。このバージョンが読めるのは %2 までです）。開くには Finbook を更新してください</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="113"/>
        <source>the file&apos;s section list</source>
        <translation>ファイルのセクション一覧</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="116"/>
        <source>the file ends before its end</source>
        <translation>本来の終端より前でファイルが終わっています</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="120"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="121"/>
        <source>a section header</source>
        <translation>セクションヘッダー</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="122"/>
        <source>section %1</source>
        <translation>セクション %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="141"/>
        <source>the file&apos;s end is damaged</source>
        <translation>ファイルの終端が破損しています</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="146"/>
        <source>its length (%1 bytes) runs past the end of the file (%2 bytes left), yet the file ends with its end marker, so the length is damaged</source>
        <translation>長さ（%1 バイト）がファイルの終わりを超えています（残り %2 バイト）が、ファイルは終端マーカーで終わっています。長さの値が破損しています</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="154"/>
        <source>the file ends inside this section (%1 bytes announced, %2 left)</source>
        <translation>このセクションの途中でファイルが終わっています（%1 バイトのはずですが、残りは %2 バイトです）</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="158"/>
        <source>the file ends inside this section; what it holds is read</source>
        <translation>このセクションの途中でファイルが終わっています。含まれている分は読み込みました</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="162"/>
        <source>a section</source>
        <translation>セクション</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="166"/>
        <source>the file ends before this section&apos;s checksum</source>
        <translation>このセクションのチェックサムの前でファイルが終わっています</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="168"/>
        <source>a section checksum</source>
        <translation>セクションのチェックサム</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="171"/>
        <source>its checksum does not match, so its bytes changed after it was saved</source>
        <translation>チェックサムが一致しないため、保存後に内容が変更されています</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="178"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="281"/>
        <source>section %1 is missing</source>
        <translation>セクション %1 がありません</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="180"/>
        <source>the end marker</source>
        <translation>終端マーカー</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="181"/>
        <source>the file</source>
        <translation>ファイル</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="217"/>
        <source>a sound clip comes before the frames</source>
        <translation>サウンドクリップがフレームより前にあります</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="224"/>
        <source>the layers come before the frames</source>
        <translation>レイヤーがフレームより前にあります</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="226"/>
        <source>the layers are repeated</source>
        <translation>レイヤーが繰り返されています</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="235"/>
        <source>the pictures come before the frames</source>
        <translation>画像がフレームより前にあります</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="237"/>
        <source>the pictures are repeated</source>
        <translation>画像が重複しています</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="246"/>
        <source>the camera comes before the frames</source>
        <translation>カメラがフレームより前にあります</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="248"/>
        <source>the camera is repeated</source>
        <translation>カメラが重複しています</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="257"/>
        <source>the swap sets come before the frames</source>
        <translation>差し替えセットがフレームより前にあります</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="259"/>
        <source>the swap sets are repeated</source>
        <translation>差し替えセットが重複しています</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="267"/>
        <source>an unknown section is left out</source>
        <translation>不明なセクションを除外しました</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="269"/>
        <source>section</source>
        <translation>セクション</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="276"/>
        <source>the section is repeated or out of order</source>
        <translation>セクションが重複しているか、順序が正しくありません</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="290"/>
        <source>the palette</source>
        <translation>パレット</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="318"/>
        <source>the end of the section could not be read</source>
        <translation>セクションの終わりを読み取れませんでした</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="319"/>
        <source>the section</source>
        <translation>セクション</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="329"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="391"/>
        <source>the document settings</source>
        <translation>ドキュメント設定</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="332"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="333"/>
        <source>the canvas size</source>
        <translation>キャンバスサイズ</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="337"/>
        <source>the canvas size %1×%2 is outside 1 to %3 pixels</source>
        <translation>キャンバスサイズ %1×%2 が 1～%3 ピクセルの範囲外です</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="343"/>
        <source>the background colour</source>
        <translation>背景色</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="344"/>
        <source>the frame rate</source>
        <translation>フレームレート</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="348"/>
        <source>the frame rate %1 is outside %2 to %3</source>
        <translation>フレームレート %1 が %2～%3 の範囲外です</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="354"/>
        <source>the loop flag</source>
        <translation>ループの設定</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="357"/>
        <source>the loop flag %1 is neither 0 nor 1</source>
        <translation>ループの設定 %1 が 0 でも 1 でもありません</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="359"/>
        <location filename="../model/src/finbook_file_reader.cpp" line="360"/>
        <source>the play range</source>
        <translation>再生範囲</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="364"/>
        <source>the play range %1 to %2 is invalid</source>
        <translation>再生範囲 %1～%2 が無効です</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="368"/>
        <source>the next id</source>
        <translation>次の ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="370"/>
        <source>the close-gap setting</source>
        <translation>隙間を閉じる設定</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="373"/>
        <source>the close-gap setting %1 is outside 0 to %2 pixels</source>
        <translation>隙間を閉じる設定 %1 が 0〜%2 ピクセルの範囲外です</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="382"/>
        <source>the next free id %1 is larger than any id can be</source>
        <translation>次の空き ID %1 が ID の上限を超えています</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="421"/>
        <source>its parts are joined in a way too costly to work out</source>
        <translation>パーツの結合が複雑すぎて解決できません</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="58"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="60"/>
        <source>the frame list</source>
        <translation>フレーム一覧</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="68"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="74"/>
        <source>a frame</source>
        <translation>フレーム</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="71"/>
        <source>the frame is cut off and is left out, with any after it</source>
        <translation>フレームが途中で切れているため、以降のフレームとともに除外しました</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="80"/>
        <source>%1; the frame is left out</source>
        <translation>%1。このフレームは除外しました</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="89"/>
        <source>a frame id</source>
        <translation>フレーム ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="90"/>
        <source>the frame</source>
        <translation>フレーム</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="91"/>
        <source>a frame hold</source>
        <translation>フレームの表示時間</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="95"/>
        <source>the hold %1 is outside 1 to %2</source>
        <translation>表示時間 %1 が 1～%2 の範囲外です</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="97"/>
        <source>the object list</source>
        <translation>オブジェクト一覧</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="104"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="110"/>
        <source>an object</source>
        <translation>オブジェクト</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="107"/>
        <source>the object is cut off and is left out, with any after it</source>
        <translation>オブジェクトが途中で切れているため、以降のオブジェクトとともに除外しました</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="116"/>
        <source>%1; the object is left out</source>
        <translation>%1。このオブジェクトは除外しました</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="121"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="122"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="212"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="213"/>
        <source>a chunk header</source>
        <translation>チャンクヘッダー</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="123"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="214"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="232"/>
        <source>a chunk</source>
        <translation>チャンク</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="124"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="222"/>
        <source>chunk</source>
        <translation>チャンク</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="132"/>
        <source>an object id</source>
        <translation>オブジェクト ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="133"/>
        <source>the object</source>
        <translation>オブジェクト</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="134"/>
        <source>the object flags</source>
        <translation>オブジェクトのフラグ</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="137"/>
        <source>the object flags 0x%1 are unknown</source>
        <translation>オブジェクトのフラグ 0x%1 は不明です</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="140"/>
        <source>the mesh density</source>
        <translation>メッシュ密度</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="143"/>
        <source>the mesh density %1 is not a number from 0 to 1000</source>
        <translation>メッシュ密度 %1 が 0～1000 の数値ではありません</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="160"/>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="166"/>
        <source>the object name</source>
        <translation>オブジェクト名</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="163"/>
        <source>the object name is %1 bytes long (at most %2)</source>
        <translation>オブジェクト名が %1 バイトあります（最大 %2 バイト）</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="174"/>
        <source>the object name is not valid UTF-8 text</source>
        <translation>オブジェクト名が有効な UTF-8 テキストではありません</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="181"/>
        <source>the stroke list</source>
        <translation>ストローク一覧</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="188"/>
        <source>a stroke id</source>
        <translation>ストローク ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="199"/>
        <source>the stroke</source>
        <translation>ストローク</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="341"/>
        <source>its pose has %n stroke(s) but the object has %1</source>
        <translation>
            <numerusform>ポーズのストローク数は %n ですが、オブジェクトのストローク数は %1 です</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="348"/>
        <source>stroke %1 has %n point(s) but its pose has %2</source>
        <translation>
            <numerusform>ストローク %1 の点の数は %n ですが、ポーズでは %2 です</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="189"/>
        <source>a stroke reference</source>
        <translation>ストロークの参照</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="49"/>
        <source>%1 claims %2 entries; the %3 that fit are read</source>
        <translation>%1 には %2 個の項目があるはずですが、収まっている %3 個を読み込みました</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="192"/>
        <source>it refers to stroke data %1 of %2</source>
        <translation>ストロークデータ %1 を参照していますが、%2 個しかありません</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="220"/>
        <source>an unknown chunk is left out</source>
        <translation>不明なチャンクを除外しました</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="227"/>
        <source>chunk %1 appears twice or with another rig</source>
        <translation>チャンク %1 が 2 回、または別のリグと一緒に現れます</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="236"/>
        <source>%1; the chunk is left out</source>
        <translation>%1。このチャンクは除外しました</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="264"/>
        <source>the skeleton&apos;s join</source>
        <translation>スケルトンの接続</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="266"/>
        <source>a join comes without a skeleton</source>
        <translation>スケルトンのない接続があります</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="274"/>
        <source>the skeleton&apos;s join is damaged</source>
        <translation>スケルトンの接続が壊れています</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="287"/>
        <source>the pin list</source>
        <translation>ピン一覧</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="292"/>
        <source>a pin id</source>
        <translation>ピン ID</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="293"/>
        <source>pin %1</source>
        <translation>ピン %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="296"/>
        <source>a pin position</source>
        <translation>ピンの位置</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="299"/>
        <source>pin %1 has a non-finite position</source>
        <translation>ピン %1 の位置が有限の値ではありません</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="310"/>
        <source>the cage corner list</source>
        <translation>ケージの頂点一覧</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="312"/>
        <source>the cage has fewer than 3 corners</source>
        <translation>ケージの頂点が 3 個未満です</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="319"/>
        <source>a cage corner</source>
        <translation>ケージの頂点</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="322"/>
        <source>cage corner %1 has a non-finite position</source>
        <translation>ケージの頂点 %1 の位置が有限の値ではありません</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="331"/>
        <source>a pose reference</source>
        <translation>ポーズの参照</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="333"/>
        <source>its pose refers to pose %1 of %2</source>
        <translation>ポーズがポーズ %1 を参照していますが、%2 個しかありません</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="337"/>
        <source>its pose: %1</source>
        <translation>ポーズ: %1</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="360"/>
        <source>%1 has no id</source>
        <translation>%1 に ID がありません</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="361"/>
        <source>%1 has the id %2, larger than any id can be</source>
        <translation>%1 の ID %2 が ID の上限を超えています</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_frames.cpp" line="369"/>
        <source>%1 has the id %2, which is already used</source>
        <translation>%1 の ID %2 はすでに使われています</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="449"/>
        <source>the next free id %1 is not above the largest id %2</source>
        <translation>次の空き ID %1 が最大の ID %2 より大きくありません</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="467"/>
        <source>the id %1 is used twice</source>
        <translation>ID %1 が 2 回使われています</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="472"/>
        <source>no frame of it could be read; there is nothing to recover</source>
        <translation>フレームを 1 つも読み取れなかったため、復元できるものがありません</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader.cpp" line="481"/>
        <source>there is not enough memory to open this file</source>
        <translation>このファイルを開くのに十分なメモリがありません</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="26"/>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="28"/>
        <source>a stroke</source>
        <translation>ストローク</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="32"/>
        <source>point %1 has a non-finite coordinate</source>
        <translation>点 %1 の座標が有限の値ではありません</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="48"/>
        <source>%n point(s) with a non-finite coordinate are left out</source>
        <translation>
            <numerusform>座標が有限の値ではない点 %n 個を除外しました</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="57"/>
        <source>the stroke table</source>
        <translation>ストロークテーブル</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="71"/>
        <source>a stroke colour</source>
        <translation>ストロークの色</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="72"/>
        <source>a stroke width</source>
        <translation>ストロークの太さ</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="74"/>
        <source>the width %1 is not a number above 0 and up to %2</source>
        <translation>太さ %1 が 0 より大きく %2 以下の数値ではありません</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="90"/>
        <source>the pose table</source>
        <translation>ポーズテーブル</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_reader_tables.cpp" line="97"/>
        <source>a pose</source>
        <translation>ポーズ</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="24"/>
        <source>the skeleton</source>
        <translation>スケルトン</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="27"/>
        <source>its skeleton has no joints</source>
        <translation>スケルトンにジョイントがありません</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="34"/>
        <source>skeleton joint %1 has a non-finite value</source>
        <translation>スケルトンのジョイント %1 に有限でない値が含まれています</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="41"/>
        <source>skeleton joint %1 has a negative radius</source>
        <translation>スケルトンのジョイント %1 の半径が負の値です</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="45"/>
        <source>skeleton joint %1 has an invalid parent</source>
        <translation>スケルトンのジョイント %1 の親が無効です</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="50"/>
        <source>the skeleton&apos;s root is not a root joint</source>
        <translation>スケルトンのルートがルートジョイントではありません</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="51"/>
        <source>the skeleton&apos;s pose has a non-finite value</source>
        <translation>スケルトンのポーズに有限でない値が含まれています</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="54"/>
        <source>a skeleton setting is outside 0 to 1</source>
        <translation>スケルトンの設定値が 0～1 の範囲外です</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="64"/>
        <source>the skeleton has an unknown skinning mode</source>
        <translation>スケルトンのスキニング方式が不明です</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="73"/>
        <source>skeleton joint %1 has an unknown lock state</source>
        <translation>スケルトンの関節 %1 のロック状態が不明です</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="84"/>
        <source>the skeleton&apos;s limb bases</source>
        <translation>スケルトンの肢の付け根</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="87"/>
        <source>limb bases come without a skeleton</source>
        <translation>スケルトンのない肢の付け根があります</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="90"/>
        <source>the skeleton has %1 joints but %2 limb base flags</source>
        <translation>スケルトンの関節は %1 個ですが、肢の付け根の印は %2 個です</translation>
    </message>
    <message>
        <location filename="../model/src/skeleton/skeleton_chunk.cpp" line="99"/>
        <source>skeleton joint %1 has an unknown limb base flag</source>
        <translation>スケルトンの関節 %1 に不明な肢の付け根の印があります</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_recover.cpp" line="51"/>
        <source>%1 damaged bytes could not be read; reading goes on with section %2</source>
        <translation>破損した %1 バイトを読み取れませんでした。セクション %2 から読み込みを続けます</translation>
    </message>
    <message>
        <location filename="../model/src/finbook_file_recover.cpp" line="59"/>
        <source>the last %1 bytes of the file are damaged and could not be read</source>
        <translation>ファイルの最後の %1 バイトが破損していて読み取れませんでした</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/finbook_file_recover.cpp" line="139"/>
        <source>%n missing or repeated id(s) were replaced by new ones</source>
        <translation>
            <numerusform>欠落または重複していた ID %n 個を新しい ID に置き換えました</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/recovery/autosaver.cpp" line="162"/>
        <source>Autosave could not write a recovery copy: %1.</source>
        <translation>自動保存で復元用のコピーを書き込めませんでした: %1。</translation>
    </message>
    <message>
        <location filename="../model/src/recovery/recovery_writer.h" line="43"/>
        <source>there is not enough memory</source>
        <translation>メモリが足りません</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="49"/>
        <source>the fill list</source>
        <translation>塗りの一覧</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="52"/>
        <source>the object claims %1 fills, more than %2</source>
        <translation>オブジェクトの塗りが %1 個あり、上限 %2 を超えています</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="42"/>
        <source>a fill&apos;s seed is not a number</source>
        <translation>塗りの基準点が数値ではありません</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="27"/>
        <source>a fill names the stroke id %1, which no stroke can have</source>
        <translation>塗りつぶしが、どのストロークにも付けられない ID %1 を参照しています</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="33"/>
        <source>a fill&apos;s stroke ids are not in order</source>
        <translation>塗りのストロークIDが順に並んでいません</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="69"/>
        <source>the fill regions</source>
        <translation>塗りの領域</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="72"/>
        <source>the object gives regions of %1 fills but has %2</source>
        <translation>オブジェクトは %1 個の塗りの領域を示していますが、塗りは %2 個です</translation>
    </message>
    <message>
        <location filename="../model/src/fill/fill_chunk.cpp" line="82"/>
        <source>the object&apos;s fills claim more than %1 regions</source>
        <translation>オブジェクトの塗りが %1 を超える領域を示しています</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="48"/>
        <location filename="../model/src/reference/reference_section.cpp" line="50"/>
        <source>the reference layer</source>
        <translation>参照レイヤー</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="52"/>
        <source>the section is repeated</source>
        <translation>セクションが重複しています</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="57"/>
        <source>the reference is of an unknown kind (%1)</source>
        <translation>参照の種類が不明です (%1)</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="61"/>
        <source>the reference has unknown flags</source>
        <translation>参照に不明なフラグがあります</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="76"/>
        <source>the reference&apos;s place, scale, rotation, opacity or rate is not a number or out of range</source>
        <translation>参照の位置・拡大率・回転・不透明度・レートが数値でないか範囲外です</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="80"/>
        <source>the reference&apos;s name is too long</source>
        <translation>参照の名前が長すぎます</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="86"/>
        <source>the reference claims %1 bytes but only %2 remain</source>
        <translation>参照は %1 バイトと記していますが、残りは %2 バイトしかありません</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="99"/>
        <source>the reference layer is left out: %1</source>
        <translation>参照レイヤーは除外されます: %1</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="106"/>
        <location filename="../model/src/reference/reference_section.cpp" line="108"/>
        <source>the reference&apos;s picture sequence</source>
        <translation>参照の連番画像</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="112"/>
        <source>it does not follow a reference picture, or is repeated</source>
        <translation>参照画像の後にないか、繰り返されています</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="115"/>
        <source>it claims %1 pictures</source>
        <translation>%1 枚の画像があるとしています</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="123"/>
        <source>picture %1 claims %2 bytes but only %3 remain</source>
        <translation>画像 %1 は %2 バイトあるとしていますが、残りは %3 バイトだけです</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_section.cpp" line="142"/>
        <source>the reference&apos;s further pictures are left out: %1</source>
        <translation>参照の2枚目以降の画像は除外されます: %1</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="17"/>
        <source>sound clip %1</source>
        <translation>サウンドクリップ %1</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="20"/>
        <location filename="../model/src/sound/sound_section.cpp" line="34"/>
        <location filename="../model/src/sound/sound_section.cpp" line="79"/>
        <source>the sound clip</source>
        <translation>サウンドクリップ</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="24"/>
        <source>%1; the sound clip is left out</source>
        <translation>%1。サウンドクリップは除外されます</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="32"/>
        <source>the file holds more than %1 sound clips</source>
        <translation>ファイルに %1 個を超えるサウンドクリップがあります</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="39"/>
        <source>the sound starts at %1, outside 0 to %2</source>
        <translation>サウンドの開始位置 %1 が 0〜%2 の範囲外です</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="46"/>
        <source>the sound&apos;s volume %1 is outside 0 to %2</source>
        <translation>サウンドの音量 %1 が 0〜%2 の範囲外です</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="54"/>
        <source>the sound flags 0x%1 are unknown</source>
        <translation>サウンドのフラグ 0x%1 が不明です</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="58"/>
        <source>the sound&apos;s name is %1 bytes long (at most %2)</source>
        <translation>サウンドの名前が %1 バイトあります(最大 %2)</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="68"/>
        <source>the sound&apos;s name is not valid UTF-8 text</source>
        <translation>サウンドの名前が有効な UTF-8 テキストではありません</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="72"/>
        <source>the sound is %1 MB long (at most %2 MB)</source>
        <translation>サウンドが %1 MB あります(最大 %2 MB)</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_section.cpp" line="76"/>
        <source>the sound clip holds no sound</source>
        <translation>サウンドクリップに音声がありません</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_chunk.cpp" line="11"/>
        <source>the fill shading list</source>
        <translation>塗りの陰影リスト</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_chunk.cpp" line="15"/>
        <source>the object shades %1 fills but has %2</source>
        <translation>オブジェクトは %1 個の塗りに陰影を付けていますが、塗りは %2 個です</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_chunk.cpp" line="22"/>
        <source>a fill&apos;s shading (%1, %2) is not one Finbook knows</source>
        <translation>塗りの陰影 (%1, %2) は Finbook の知らないものです</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_chunk.cpp" line="34"/>
        <source>the light</source>
        <translation>光源</translation>
    </message>
    <message>
        <location filename="../model/src/shade/shade_chunk.cpp" line="40"/>
        <source>the light&apos;s direction (%1°, %2°) is outside 0 to 360° and 0 to 90°</source>
        <translation>光源の向き (%1°, %2°) が 0〜360° と 0〜90° の範囲外です</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_section.cpp" line="13"/>
        <location filename="../model/src/camera/camera_section.cpp" line="15"/>
        <source>the camera</source>
        <translation>カメラ</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_section.cpp" line="20"/>
        <source>the camera has %1 keys (at most %2)</source>
        <translation>カメラのキーが %1 個あります（上限 %2）</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_section.cpp" line="40"/>
        <source>camera key %1 holds a value out of range; it is left out</source>
        <translation>カメラキー %1 の値が範囲外です。省きます</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_section.cpp" line="46"/>
        <source>camera key %1 is not after the key before it; it is left out</source>
        <translation>カメラキー %1 が前のキーより後にありません。省きます</translation>
    </message>
    <message>
        <location filename="../model/src/camera/camera_section.cpp" line="59"/>
        <source>%1; the camera is left out</source>
        <translation>%1。カメラを省きます</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="14"/>
        <location filename="../model/src/scene/layer_section.cpp" line="16"/>
        <source>the layers</source>
        <translation>レイヤー</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="20"/>
        <source>the file has %1 layers (1 to %2)</source>
        <translation>ファイルのレイヤー数は %1 です（1〜%2）</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="28"/>
        <source>the layer</source>
        <translation>レイヤー</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="39"/>
        <source>its opacity is not between 0 and 1</source>
        <translation>不透明度が 0〜1 の範囲外です</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="44"/>
        <source>its depth is not between %1 and %2</source>
        <translation>奥行きが %1〜%2 の範囲外です</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="59"/>
        <source>the layers hold %1 frames, but the file has %2</source>
        <translation>レイヤーのフレーム数は %1 ですが、ファイルには %2 あります</translation>
    </message>
    <message>
        <location filename="../model/src/scene/layer_section.cpp" line="76"/>
        <source>%1; every frame is put on one layer</source>
        <translation>%1。すべてのフレームを1つのレイヤーに入れます</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="14"/>
        <location filename="../model/src/swap/swap_section.cpp" line="16"/>
        <location filename="../model/src/swap/swap_section.cpp" line="52"/>
        <source>the swap sets</source>
        <translation>差し替えセット</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="21"/>
        <source>the file has %1 swap sets (at most %2)</source>
        <translation>ファイルに差し替えセットが %1 個あります（最大 %2）</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="28"/>
        <source>swap set %1</source>
        <translation>差し替えセット %1</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="33"/>
        <source>swap set %1 has %2 drawings (1 to %3)</source>
        <translation>差し替えセット %1 に絵が %2 枚あります（1〜%3）</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="44"/>
        <source>a drawing of swap set %1 carries a pose</source>
        <translation>差し替えセット %1 の絵にポーズが付いています</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="65"/>
        <source>object %1 shows a drawing the swap sets do not hold</source>
        <translation>オブジェクト %1 が差し替えセットにない絵を表示しています</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="83"/>
        <source>the swap sets link objects the frames do not hold</source>
        <translation>差し替えセットがフレームにないオブジェクトを参照しています</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="95"/>
        <source>a frame shows a swap set on two objects</source>
        <translation>1 つのフレームで 2 つのオブジェクトが同じ差し替えセットを表示しています</translation>
    </message>
    <message>
        <location filename="../model/src/swap/swap_section.cpp" line="113"/>
        <source>%1; the swap sets are left out</source>
        <translation>%1。差し替えセットは読み込みません</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="106"/>
        <location filename="../model/src/picture/picture_section.cpp" line="107"/>
        <location filename="../model/src/picture/picture_section.cpp" line="251"/>
        <source>the pictures</source>
        <translation>画像</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="118"/>
        <source>picture %1 is cut off</source>
        <translation>画像 %1 が途中で切れています</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="124"/>
        <source>picture %1&apos;s mesh has %2 vertices</source>
        <translation>画像 %1 のメッシュの頂点数が %2 です</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="133"/>
        <source>picture %1&apos;s mesh has a vertex outside the picture</source>
        <translation>画像 %1 のメッシュに画像の外の頂点があります</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="140"/>
        <source>picture %1&apos;s mesh has no triangles</source>
        <translation>画像 %1 のメッシュに三角形がありません</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="148"/>
        <source>picture %1&apos;s mesh names a vertex it does not have</source>
        <translation>画像 %1 のメッシュが存在しない頂点を参照しています</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="157"/>
        <source>picture %1&apos;s mesh has a triangle turned over or without area</source>
        <translation>画像 %1 のメッシュに裏返った三角形か面積のない三角形があります</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="167"/>
        <source>picture %1 is %2 × %3 pixels: %4</source>
        <translation>画像 %1 は %2 × %3 ピクセルです：%4</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="181"/>
        <location filename="../model/src/picture/picture_section.cpp" line="191"/>
        <source>picture %1 does not decode: %2</source>
        <translation>画像 %1 をデコードできません：%2</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="196"/>
        <source>picture %1 is %2 × %3 pixels, not the %4 × %5 it claims</source>
        <translation>画像 %1 は %2 × %3 ピクセルで、記載の %4 × %5 ではありません</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="208"/>
        <source>%1; the objects showing it are left without it</source>
        <translation>%1。この画像を表示するオブジェクトは画像なしで開きます</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="220"/>
        <source>the object&apos;s picture</source>
        <translation>オブジェクトの画像</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="228"/>
        <source>the picture&apos;s place is out of range</source>
        <translation>画像の位置が範囲外です</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="236"/>
        <source>the picture&apos;s pose has a point out of range</source>
        <translation>画像のポーズに範囲外の点があります</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="259"/>
        <source>an object shows picture %1, which the file does not hold</source>
        <translation>オブジェクトがファイルにない画像 %1 を表示しています</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_section.cpp" line="284"/>
        <source>a picture&apos;s pose does not fit its mesh; it is shown at rest</source>
        <translation>画像のポーズがメッシュと合いません。レストの状態で表示します</translation>
    </message>
</context>
<context>
    <name>MeshImport</name>
    <message>
        <location filename="../model/src/import/mesh_import.cpp" line="22"/>
        <source>Cannot import &quot;%1&quot;: %2</source>
        <translation>「%1」をインポートできません: %2</translation>
    </message>
    <message>
        <location filename="../model/src/import/mesh_import.cpp" line="27"/>
        <source>Cannot import &quot;%1&quot;: the mesh has no boundary to draw.</source>
        <translation>「%1」をインポートできません: メッシュに描画できる境界がありません。</translation>
    </message>
</context>
<context>
    <name>ObjectListModel</name>
    <message numerus="yes">
        <location filename="../model/src/object_list_model.cpp" line="170"/>
        <source>%1: %n stroke(s)</source>
        <translation>
            <numerusform>%1: ストローク %n 本</numerusform>
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
        <translation>黒</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="48"/>
        <source>Grey</source>
        <translation>灰色</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="49"/>
        <source>White</source>
        <translation>白</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="49"/>
        <source>Purple</source>
        <translation>紫</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="50"/>
        <source>Blue</source>
        <translation>青</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="50"/>
        <source>Red</source>
        <translation>赤</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="51"/>
        <source>Orange</source>
        <translation>オレンジ</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="51"/>
        <source>Yellow</source>
        <translation>黄</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="52"/>
        <source>Green</source>
        <translation>緑</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="52"/>
        <source>Brown</source>
        <translation>茶</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="75"/>
        <source>it is not a GIMP palette (its first line is not &quot;GIMP Palette&quot;)</source>
        <translation>GIMP パレットではありません（1 行目が &quot;GIMP Palette&quot; ではありません）</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="97"/>
        <source>line %1: channels &quot;%2&quot; are not RGB or RGBA</source>
        <translation>%1 行目: チャンネル &quot;%2&quot; は RGB でも RGBA でもありません</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="117"/>
        <source>line %1 is not a colour (%2 numbers from 0 to 255, then a name)</source>
        <translation>%1 行目は色ではありません（0〜255 の数が %2 個、その後に名前）</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="124"/>
        <source>it holds more than %1 colours</source>
        <translation>%1 色より多くの色を含んでいます</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="176"/>
        <source>the palette is damaged</source>
        <translation>パレットが壊れています</translation>
    </message>
    <message>
        <location filename="../model/src/palette/palette.cpp" line="182"/>
        <source>the palette claims %1 colours</source>
        <translation>パレットが %1 色あると主張しています</translation>
    </message>
</context>
<context>
    <name>PictureImport</name>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="126"/>
        <source>Its stack.xml does not describe an OpenRaster image.</source>
        <translation>stack.xml が OpenRaster 画像を記述していません。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="136"/>
        <source>Its stack.xml gives a layer an invalid position or opacity.</source>
        <translation>stack.xml でレイヤーの位置か不透明度が不正です。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="142"/>
        <source>Its layer groups are nested too deeply.</source>
        <translation>レイヤーグループの入れ子が深すぎます。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="148"/>
        <source>Its stack.xml names a layer without a picture.</source>
        <translation>stack.xml に画像のないレイヤーがあります。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="152"/>
        <source>It has more than %1 layers.</source>
        <translation>レイヤーが %1 を超えています。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="159"/>
        <source>Its stack.xml is malformed (line %1: %2).</source>
        <translation>stack.xml の形式が正しくありません（%1 行目: %2）。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="164"/>
        <source>Its stack.xml is empty.</source>
        <translation>stack.xml が空です。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="167"/>
        <source>Its stack of layers is empty.</source>
        <translation>レイヤーのスタックが空です。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="177"/>
        <source>The picture of its layer “%1” (%2) is missing.</source>
        <translation>レイヤー「%1」の画像（%2）がありません。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="182"/>
        <source>The picture of its layer “%1” is larger than %2 MB.</source>
        <translation>レイヤー「%1」の画像が %2 MB を超えています。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="187"/>
        <source>The picture of its layer “%1” is damaged or cut short in the file.</source>
        <translation>レイヤー「%1」の画像がファイル内で壊れているか途中で切れています。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="196"/>
        <source>Its layer “%1”: %2</source>
        <translation>レイヤー「%1」: %2</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="216"/>
        <source>It is a zip archive, but not an OpenRaster picture.</source>
        <translation>zip アーカイブですが、OpenRaster 画像ではありません。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="237"/>
        <source>It is not a zip archive, or it is damaged or cut short.</source>
        <translation>zip アーカイブではないか、破損しているか途中で切れています。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="244"/>
        <source>It has no stack.xml: it is not an OpenRaster picture.</source>
        <translation>stack.xml がありません。OpenRaster 画像ではありません。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="248"/>
        <source>Its stack.xml is larger than %1 MB.</source>
        <translation>stack.xml が %1 MB を超えています。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="252"/>
        <source>Its stack.xml is damaged or cut short.</source>
        <translation>stack.xml が破損しているか途中で切れています。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/openraster.cpp" line="272"/>
        <source>It has no visible layer.</source>
        <translation>表示されるレイヤーがありません。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="23"/>
        <source>“%1” cannot be imported: %2</source>
        <translation>「%1」は読み込めません: %2</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="30"/>
        <source>Its picture has no size.</source>
        <translation>画像に大きさがありません。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="32"/>
        <source>It claims to be %1 × %2 pixels; a picture may be at most %3 pixels wide and high.</source>
        <translation>%1 × %2 ピクセルとされていますが、画像の幅と高さは最大 %3 ピクセルです。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="40"/>
        <source>It claims to be %1 × %2 pixels; a picture may have at most %3 megapixels.</source>
        <translation>%1 × %2 ピクセルとされていますが、画像は最大 %3 メガピクセルです。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="47"/>
        <source>Its pictures together would take more than %1 MB of memory.</source>
        <translation>画像を合わせると %1 MB を超えるメモリが必要です。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="72"/>
        <source>Its picture is cut short (the file is incomplete).</source>
        <translation>画像が途中で切れています（ファイルが不完全です）。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="83"/>
        <source>Its picture cannot be decoded: the file is damaged, cut short or too large.</source>
        <translation>画像をデコードできません。ファイルが破損しているか、途中で切れているか、大きすぎます。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="94"/>
        <location filename="../model/src/picture/picture_import.cpp" line="36"/>
        <source>It is empty.</source>
        <translation>空です。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="102"/>
        <source>It holds a picture of a kind Finbook cannot read.</source>
        <translation>Finbook が読めない種類の画像です。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="111"/>
        <source>Its picture cannot be decoded.</source>
        <translation>画像をデコードできません。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_decode.cpp" line="118"/>
        <source>There is not enough memory to read it.</source>
        <translation>読み込むためのメモリが足りません。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_import.cpp" line="33"/>
        <source>It cannot be read (is it there, and may Finbook read it?).</source>
        <translation>読み込めません（ファイルは存在し、Finbook に読み取り権限がありますか？）。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_import.cpp" line="45"/>
        <location filename="../model/src/picture/picture_import.cpp" line="49"/>
        <source>It is larger than %1 MB.</source>
        <translation>%1 MB を超えています。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="44"/>
        <source>The picture is empty.</source>
        <translation>画像が空です。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="49"/>
        <location filename="../model/src/picture/picture_object.cpp" line="275"/>
        <source>There is not enough memory for the picture.</source>
        <translation>画像のためのメモリが足りません。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="55"/>
        <source>The picture could not be encoded to be saved: %1</source>
        <translation>保存用に画像をエンコードできませんでした：%1</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="71"/>
        <source>The picture&apos;s outline cannot be traced: %1</source>
        <translation>画像の輪郭を抽出できません：%1</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="75"/>
        <source>The picture is fully transparent: nothing of it shows.</source>
        <translation>画像が完全に透明で、何も見えません。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="87"/>
        <source>The picture&apos;s outline cannot be meshed: %1</source>
        <translation>画像の輪郭をメッシュにできません：%1</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="288"/>
        <source>The object has no picture.</source>
        <translation>オブジェクトに画像がありません。</translation>
    </message>
    <message>
        <location filename="../model/src/picture/picture_object.cpp" line="268"/>
        <source>The posed picture is too large to keep (at most %1 pixels wide and high).</source>
        <translation>ポーズをつけた画像が大きすぎて保持できません（幅と高さは最大 %1 ピクセル）。</translation>
    </message>
</context>
<context>
    <name>QCommandLineParser</name>
    <message>
        <location filename="../app/main.cpp" line="26"/>
        <source>Displays help on commandline options.</source>
        <translation>コマンドラインオプションのヘルプを表示する。</translation>
    </message>
    <message>
        <location filename="../app/main.cpp" line="27"/>
        <source>Displays help including Qt specific options.</source>
        <translation>Qt 固有のオプションを含むヘルプを表示する。</translation>
    </message>
</context>
<context>
    <name>Reference</name>
    <message>
        <location filename="../model/src/reference/reference_commands.cpp" line="16"/>
        <source>Import Reference</source>
        <translation>参照を読み込む</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_commands.cpp" line="18"/>
        <source>Reference Opacity</source>
        <translation>参照の不透明度</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_commands.cpp" line="20"/>
        <source>Show or Hide Reference</source>
        <translation>参照の表示/非表示</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_commands.cpp" line="22"/>
        <source>Lock or Unlock Reference</source>
        <translation>参照のロック/ロック解除</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/tool_reference.cpp" line="26"/>
        <location filename="../model/src/reference/reference_commands.cpp" line="24"/>
        <source>Move Reference</source>
        <translation>参照を移動</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/tool_reference.cpp" line="22"/>
        <location filename="../model/src/reference/reference_commands.cpp" line="26"/>
        <source>Scale Reference</source>
        <translation>参照を拡大縮小</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/tool_reference.cpp" line="24"/>
        <location filename="../model/src/reference/reference_commands.cpp" line="28"/>
        <source>Rotate Reference</source>
        <translation>参照を回転</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_commands.cpp" line="30"/>
        <source>Reference Frame Rate</source>
        <translation>参照のフレームレート</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_commands.cpp" line="91"/>
        <source>Remove Reference</source>
        <translation>参照を削除</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_import.cpp" line="34"/>
        <source>“%1” cannot be used as a reference: %2</source>
        <translation>「%1」は参照として使えません: %2</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_import.cpp" line="44"/>
        <source>It cannot be read (is it there, and may Finbook read it?).</source>
        <translation>読み込めません (ファイルは存在し、Finbook に読み取り権限がありますか?)。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_import.cpp" line="67"/>
        <source>It is larger than %1 MB.</source>
        <translation>%1 MB を超えています。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_import.cpp" line="53"/>
        <source>It is empty.</source>
        <translation>空です。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_media.cpp" line="111"/>
        <location filename="../model/src/reference/reference_media.cpp" line="135"/>
        <source>The file is empty.</source>
        <translation>ファイルが空です。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_media.cpp" line="69"/>
        <source>Its picture cannot be decoded.</source>
        <translation>画像をデコードできません。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="85"/>
        <source>Its SVG declares entities, which Finbook does not expand.</source>
        <translation>この SVG はエンティティを宣言していますが、Finbook は展開しません。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="113"/>
        <location filename="../model/src/reference/reference_svg.cpp" line="215"/>
        <source>It is not a valid SVG picture.</source>
        <translation>有効な SVG 画像ではありません。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="152"/>
        <source>Its SVG uses an element inside itself (a loop of &lt;use&gt;).</source>
        <translation>この SVG は要素をそれ自身の中で使っています（&lt;use&gt; のループ）。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="210"/>
        <source>SVG pictures are drawn only where Finbook runs with its graphical application (their text needs its fonts).</source>
        <translation>SVG 画像は Finbook がグラフィカルアプリケーションとして動作しているときだけ描画されます（テキストにそのフォントが必要です）。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="185"/>
        <source>The reference&apos;s SVG pictures took all the time Finbook spends drawing them.</source>
        <translation>参照の SVG 画像が、Finbook がその描画に費やす時間をすべて使いました。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="193"/>
        <source>Its compressed SVG is damaged or larger than 16 MB.</source>
        <translation>圧縮された SVG が壊れているか、16 MB を超えています。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="197"/>
        <source>Its SVG is larger than 16 MB.</source>
        <translation>SVG が 16 MB を超えています。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="204"/>
        <source>Its SVG paints more than 100,000 elements (counting what &lt;use&gt; repeats), more than Finbook draws for a reference.</source>
        <translation>この SVG は 100,000 を超える要素を描画します（&lt;use&gt; の繰り返しを含む）。Finbook が参照として描画する量を超えています。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="221"/>
        <source>Its SVG has no size.</source>
        <translation>SVG にサイズがありません。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="228"/>
        <location filename="../model/src/reference/video_decoder.cpp" line="184"/>
        <location filename="../model/src/reference/video_decoder.cpp" line="189"/>
        <location filename="../model/src/reference/video_decoder.cpp" line="193"/>
        <location filename="../model/src/reference/video_decoder.cpp" line="221"/>
        <source>There is not enough memory to read it.</source>
        <translation>読み込むためのメモリが足りません。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_svg.cpp" line="257"/>
        <source>Its SVG takes too long to draw (more than %1 s), more than Finbook spends on a reference.</source>
        <translation>この SVG は描画に時間がかかりすぎます（%1 秒超）。Finbook が参照に費やす時間を超えています。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/video_decoder.cpp" line="197"/>
        <location filename="../model/src/reference/video_decoder.cpp" line="201"/>
        <source>It is not a picture or a video Finbook can read, or it is damaged.</source>
        <translation>Finbook が読める画像や動画ではないか、壊れています。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/video_decoder.cpp" line="204"/>
        <source>It is damaged: its streams cannot be read.</source>
        <translation>壊れています: ストリームを読み込めません。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/video_decoder.cpp" line="208"/>
        <source>It holds no picture Finbook can decode.</source>
        <translation>Finbook がデコードできる画像が含まれていません。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/video_decoder.cpp" line="213"/>
        <source>Its pictures are empty or larger than 16384 pixels a side.</source>
        <translation>画像が空か、一辺が 16384 ピクセルを超えています。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/video_decoder.cpp" line="231"/>
        <source>Its pictures cannot be decoded.</source>
        <translation>画像をデコードできません。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/video_decoder.cpp" line="238"/>
        <source>Its first picture cannot be decoded.</source>
        <translation>最初の画像をデコードできません。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_sequence.cpp" line="75"/>
        <source>No picture was chosen.</source>
        <translation>画像が選ばれていません。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_sequence.cpp" line="78"/>
        <source>A sequence of more than %1 pictures cannot be used as a reference.</source>
        <translation>%1 枚を超える連番画像は参照に使えません。</translation>
    </message>
    <message>
        <location filename="../model/src/reference/reference_sequence.cpp" line="87"/>
        <source>The pictures together are larger than %1 MB.</source>
        <translation>画像の合計が %1 MB を超えています。</translation>
    </message>
    <message numerus="yes">
        <location filename="../model/src/reference/reference_sequence.cpp" line="108"/>
        <source>%1 and %n more</source>
        <extracomment>%1 is the first file&apos;s name, %n how many pictures follow it</extracomment>
        <translation>
            <numerusform>%1 ほか %n 枚</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RigPrompt</name>
    <message>
        <location filename="../ui/src/rig/rig_prompt.cpp" line="20"/>
        <source>&quot;%1&quot; is posed. Removing its rig sends the drawing back to rest. (Apply Pose to Drawing first keeps the pose.)</source>
        <translation>「%1」はポーズ中です。リグを削除すると絵は初期状態に戻ります。(先に「ポーズを絵に適用」するとポーズが残ります。)</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/rig_prompt.cpp" line="24"/>
        <source>Discard the Pose?</source>
        <translation>ポーズを破棄しますか？</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/rig_prompt.cpp" line="22"/>
        <source>&quot;%1&quot; is posed. Replacing its rig sends the drawing back to rest. (Apply Pose to Drawing first keeps the pose.)</source>
        <translation>「%1」にはポーズが付いています。リグを置き換えると、絵は元の状態に戻ります（先に「ポーズを絵に適用」を実行すれば、ポーズを残せます）。</translation>
    </message>
</context>
<context>
    <name>Sound</name>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="90"/>
        <source>The file is not a sound Finbook can read (WAV, FLAC, MP3, Ogg, Opus, AAC or M4A), or it is damaged.</source>
        <translation>このファイルは Finbook が読めるサウンド(WAV、FLAC、MP3、Ogg、Opus、AAC、M4A)ではないか、破損しています。</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="211"/>
        <source>It holds more sound than a file of %1 KB can hold when it is real sound (more than %2 min; hostile or damaged files announce hours of sound in a few kilobytes). Convert it to WAV, FLAC or MP3 and import it again.</source>
        <translation>%1 KB のファイルに実際の音として入りうる量を超える音を含んでいます（%2 分超。悪意のある、または壊れたファイルは数 KB で何時間もの音を宣言します）。WAV、FLAC または MP3 に変換して、もう一度読み込んでください。</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="240"/>
        <source>With the soundtrack&apos;s other clips it would make more than %1 min of sound, the most Finbook decodes from sound files of this size.</source>
        <translation>サウンドトラックのほかのクリップと合わせると %1 分を超え、このサイズのサウンドファイルから Finbook がデコードする上限を超えます。</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="251"/>
        <source>The file is empty.</source>
        <translation>ファイルが空です。</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="253"/>
        <source>The file is incomplete: its sound data is cut off. Import the complete file.</source>
        <translation>ファイルが不完全です。サウンドデータが途中で切れています。完全なファイルをインポートしてください。</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="261"/>
        <location filename="../model/src/sound/sound_decode.cpp" line="265"/>
        <location filename="../model/src/sound/sound_decode.cpp" line="269"/>
        <location filename="../model/src/sound/sound_decode.cpp" line="305"/>
        <source>There is not enough memory to read the sound.</source>
        <translation>サウンドを読み込むためのメモリが足りません。</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="279"/>
        <source>The file holds no sound Finbook can play.</source>
        <translation>ファイルに Finbook が再生できるサウンドがありません。</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="197"/>
        <source>Its sample rate, %1 Hz, is outside the %2 to %3 Hz Finbook plays (real recordings use 8,000 to 192,000).</source>
        <translation>サンプリングレート %1 Hz は Finbook が再生する %2～%3 Hz の範囲外です（実際の録音は 8,000～192,000 を使います）。</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="294"/>
        <source>It has %1 channels; Finbook plays at most %2.</source>
        <translation>%1 チャンネルあります。Finbook が再生するのは最大 %2 チャンネルです。</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="353"/>
        <source>The sound is longer than %1 minutes, the longest Finbook plays.</source>
        <translation>サウンドが Finbook で再生できる最長の %1 分を超えています。</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="362"/>
        <source>The file holds no sound Finbook can play (no audio could be decoded from it).</source>
        <translation>ファイルに Finbook が再生できるサウンドがありません(音声をデコードできませんでした)。</translation>
    </message>
    <message>
        <location filename="../model/src/sound/sound_decode.cpp" line="369"/>
        <source>The file is incomplete: it announces %1 s of sound but holds only %2 s. Import the complete file.</source>
        <translation>ファイルが不完全です。%1 秒のサウンドと記されていますが、%2 秒しかありません。完全なファイルをインポートしてください。</translation>
    </message>
</context>
<context>
    <name>StrokeEditing</name>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="124"/>
        <source>There is no frame to draw on. Insert a frame first.</source>
        <translation>描画するフレームがありません。先にフレームを挿入してください。</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="127"/>
        <source>The object &quot;%1&quot; is locked. Unlock it in the Objects panel to draw on it.</source>
        <translation>オブジェクト「%1」はロックされています。描画するには、オブジェクトパネルでロックを解除してください。</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="130"/>
        <source>The object &quot;%1&quot; is hidden. Show it in the Objects panel to draw on it.</source>
        <translation>オブジェクト「%1」は非表示です。描画するには、オブジェクトパネルで表示してください。</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="152"/>
        <source>Object</source>
        <translation>オブジェクト</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="191"/>
        <source>%1 (pose applied)</source>
        <translation>%1（ポーズ適用済み）</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="288"/>
        <source>Delete Strokes</source>
        <translation>ストロークを削除</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="288"/>
        <source>Delete Picture</source>
        <translation>画像を削除</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="410"/>
        <source>Cut</source>
        <translation>切り取り</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="486"/>
        <source>The clipboard holds strokes this version of Finbook cannot read.</source>
        <translation>クリップボードには、このバージョンの Finbook では読み込めないストロークが入っています。</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="496"/>
        <location filename="../ui/src/tools/stroke_editing.cpp" line="497"/>
        <source>Paste</source>
        <translation>貼り付け</translation>
    </message>
</context>
<context>
    <name>Thumbnail</name>
    <message>
        <location filename="../app/thumbnail/first_frame.cpp" line="54"/>
        <source>it is not a regular file</source>
        <translation>通常のファイルではありません</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/first_frame.cpp" line="393"/>
        <source>Cannot make a thumbnail of &quot;%1&quot;: %2</source>
        <translation>「%1」のサムネイルを作成できません: %2</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/first_frame.cpp" line="442"/>
        <source>a checksum does not match, so the file is damaged.</source>
        <translation>チェックサムが一致しないため、ファイルが破損しています。</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/first_frame.cpp" line="444"/>
        <source>it holds data that this version of Finbook does not know.</source>
        <translation>このバージョンの Finbook が知らないデータが含まれています。</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/first_frame.cpp" line="447"/>
        <source>the file is damaged or incomplete.</source>
        <translation>ファイルが破損しているか不完全です。</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/thumbnail_command.cpp" line="138"/>
        <source>Usage: finbook thumbnail FILE OUT.png SIZE</source>
        <translation>使い方: finbook thumbnail ファイル 出力.png サイズ</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/thumbnail_command.cpp" line="144"/>
        <source>The thumbnail size &quot;%1&quot; is not a whole number from 1 to %2.</source>
        <translation>サムネイルのサイズ「%1」は 1 から %2 までの整数ではありません。</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/thumbnail_command.cpp" line="153"/>
        <source>Cannot make a thumbnail of &quot;%1&quot;: it has no frame.</source>
        <translation>「%1」のサムネイルを作成できません: フレームがありません。</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/thumbnail_command.cpp" line="163"/>
        <source>Cannot make a thumbnail of &quot;%1&quot;: there is not enough memory.</source>
        <translation>「%1」のサムネイルを作成できません: メモリが足りません。</translation>
    </message>
    <message>
        <location filename="../app/thumbnail/thumbnail_command.cpp" line="169"/>
        <source>Cannot write the thumbnail &quot;%1&quot;: %2.</source>
        <translation>サムネイル「%1」を書き込めません: %2。</translation>
    </message>
</context>
<context>
    <name>finbook::model::FrameListModel</name>
    <message numerus="yes">
        <location filename="../model/src/frame_list_model.cpp" line="151"/>
        <source>Frame %1, held for %n frame(s)</source>
        <translation>
            <numerusform>フレーム %1（%n フレーム分表示）</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/src/frame_list_model.cpp" line="152"/>
        <source>Frame %1</source>
        <translation>フレーム %1</translation>
    </message>
</context>
<context>
    <name>finbook::model::lipsync</name>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="31"/>
        <source>The file holds no mouth shapes.</source>
        <translation>このファイルには口の形がありません。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="44"/>
        <source>The file is larger than %1 MiB, too large for lip sync timings.</source>
        <translation>ファイルが %1 MiB を超えています。リップシンクのタイミングとしては大きすぎます。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="55"/>
        <source>The file is empty.</source>
        <translation>ファイルが空です。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="149"/>
        <source>Line %1: &quot;%2&quot; is not a time from 0 to %3 seconds.</source>
        <translation>%1 行目：「%2」は 0〜%3 秒の時間ではありません。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="158"/>
        <source>Line %1: the time goes backwards.</source>
        <translation>%1 行目：時間が逆戻りしています。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="165"/>
        <source>Line %1: the mouth cue ends before it starts.</source>
        <translation>%1 行目：口の形が始まる前に終わっています。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="172"/>
        <source>The file holds more than %1 mouth cues.</source>
        <translation>ファイルに口の形が %1 個を超えてあります。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="179"/>
        <source>Line %1: &quot;%2&quot; is not a mouth shape.</source>
        <translation>%1 行目：「%2」は口の形ではありません。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="213"/>
        <source>The frame rate %1 is not a number above 0 and up to %2.</source>
        <translation>フレームレート %1 は 0 より大きく %2 以下の数ではありません。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="221"/>
        <source>The file ends too early, after line %1.</source>
        <translation>ファイルが %1 行目のあとで途切れています。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="228"/>
        <source>Line %1: &quot;%2&quot; is not a whole number from %3 to %4.</source>
        <translation>%1 行目：「%2」は %3〜%4 の整数ではありません。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="256"/>
        <source>The Papagayo file holds no phonemes.</source>
        <translation>Papagayo ファイルに音素がありません。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="299"/>
        <source>Line 1: a Papagayo file starts with &quot;lipsync version 1&quot;.</source>
        <translation>1 行目：Papagayo ファイルは「lipsync version 1」で始まります。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="309"/>
        <source>Line %1: the frame rate &quot;%2&quot; is not a number above 0 and up to %3.</source>
        <translation>%1 行目：フレームレート「%2」は 0 より大きく %3 以下の数ではありません。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="354"/>
        <source>Line %1 is not a word (&quot;text, start frame, end frame, phoneme count&quot;).</source>
        <translation>%1 行目は単語（「テキスト、開始フレーム、終了フレーム、音素数」）ではありません。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="380"/>
        <source>Line %1 is not a phoneme (&quot;frame name&quot;).</source>
        <translation>%1 行目は音素（「フレーム 名前」）ではありません。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="388"/>
        <source>Line %1: the phoneme at frame %2 comes after its word&apos;s end, frame %3.</source>
        <translation>%1 行目：フレーム %2 の音素が単語の終わり（フレーム %3）より後にあります。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="438"/>
        <source>The XML is damaged at line %1: %2.</source>
        <translation>XML の %1 行目が壊れています：%2。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="478"/>
        <source>Mouth cue %1: its &quot;%2&quot; is not a time from 0 to %3 seconds.</source>
        <translation>口の形 %1：「%2」が 0〜%3 秒の時間ではありません。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="501"/>
        <source>Mouth cue %1 ends before it starts.</source>
        <translation>口の形 %1 が始まる前に終わっています。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="508"/>
        <source>Mouth cue %1: its &quot;value&quot; &quot;%2&quot; is not a mouth shape.</source>
        <translation>口の形 %1：「value」の「%2」は口の形ではありません。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="514"/>
        <source>Mouth cue %1: the time goes backwards.</source>
        <translation>口の形 %1：時間が逆戻りしています。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="537"/>
        <source>The JSON is damaged at character %1: %2.</source>
        <translation>JSON の %1 文字目が壊れています：%2。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="543"/>
        <source>The JSON has no &quot;mouthCues&quot; list: it is not a Rhubarb Lip Sync result.</source>
        <translation>JSON に「mouthCues」のリストがありません。Rhubarb Lip Sync の結果ではありません。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="566"/>
        <source>Line %1: the XML&apos;s root is &lt;%2&gt;, not &lt;rhubarbResult&gt;: it is not a Rhubarb Lip Sync result.</source>
        <translation>%1 行目：XML のルートが &lt;rhubarbResult&gt; ではなく &lt;%2&gt; です。Rhubarb Lip Sync の結果ではありません。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="601"/>
        <source>Line %1 is not &quot;seconds, tab, shape letter&quot;.</source>
        <translation>%1 行目が「秒、タブ、形の文字」ではありません。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="629"/>
        <source>Line %1: Moho switch data starts with &quot;MohoSwitch1&quot;.</source>
        <translation>%1 行目：Moho スイッチデータは「MohoSwitch1」で始まります。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="644"/>
        <source>Line %1 is not &quot;frame shape&quot;.</source>
        <translation>%1 行目が「フレーム 形」ではありません。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="649"/>
        <source>Line %1: &quot;%2&quot; is not a frame number from 1 to %3.</source>
        <translation>%1 行目：「%2」は 1〜%3 のフレーム番号ではありません。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="671"/>
        <source>Line %1: the letter &quot;%2&quot; is among Preston Blair&apos;s names; a file uses one naming or the other.</source>
        <translation>%1 行目：文字「%2」が Preston Blair 式の名前と混在しています。ファイルではどちらか一方の名前を使います。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="724"/>
        <source>&quot;%1&quot; could not be opened: %2.</source>
        <translation>「%1」を開けませんでした：%2。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="746"/>
        <source>&quot;%1&quot; is not lip sync timings that Finbook reads: Papagayo (.pgo), Moho switch data (.dat) or Rhubarb Lip Sync (.tsv, .json, .xml).</source>
        <translation>「%1」は Finbook が読めるリップシンクのタイミングではありません：Papagayo（.pgo）、Moho スイッチデータ（.dat）、Rhubarb Lip Sync（.tsv、.json、.xml）。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/lipsync_import.cpp" line="756"/>
        <source>Lip sync timings</source>
        <translation>リップシンクのタイミング</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="137"/>
        <source>The sound&apos;s sample rate (%1 Hz) is not one speech can be recognised at.</source>
        <translation>音声のサンプリングレート（%1 Hz）では音声認識ができません。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="142"/>
        <source>The sound is too short to hold speech (less than a tenth of a second).</source>
        <translation>音声が短すぎて発話を含められません（0.1 秒未満）。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="146"/>
        <source>The sound is damaged: some of its samples are not numbers.</source>
        <translation>音声が壊れています：一部のサンプルが数値ではありません。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="151"/>
        <source>The sound is silent: there is no speech to recognise. Check that the clip is the one with the dialogue and that it is not muted.</source>
        <translation>音声が無音で、認識する発話がありません。台詞のクリップか、ミュートされていないかを確かめてください。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="173"/>
        <source>The speech models are not installed (looked in %1; on Debian and Ubuntu install the package pocketsphinx-en-us). Mouth shapes follow the loudness only.</source>
        <translation>音声モデルがインストールされていません（%1 を探しました。Debian と Ubuntu ではパッケージ pocketsphinx-en-us をインストールしてください）。口の形は音量だけに従います。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="520"/>
        <source>The dialogue could not be prepared for recognition: %1</source>
        <translation>台詞を認識用に準備できませんでした：%1</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="529"/>
        <source>The speech models are damaged: %1</source>
        <translation>音声モデルが壊れています：%1</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="593"/>
        <source>Speech recognition failed: %1</source>
        <translation>音声認識に失敗しました：%1</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="602"/>
        <source>Lip sync was canceled.</source>
        <translation>リップシンクを取り消しました。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="854"/>
        <source>The speech models could not be loaded (%1). Mouth shapes follow the loudness only.</source>
        <translation>音声モデルを読み込めませんでした（%1）。口の形は音量だけに従います。</translation>
    </message>
    <message>
        <location filename="../model/src/lipsync/speech_recognizer.cpp" line="866"/>
        <source>The dialogue does not match the sound: the mouth follows the phones heard, without the dialogue.</source>
        <translation>台詞が音声と合いません。口は台詞なしで、聞き取った音に従います。</translation>
    </message>
</context>
<context>
    <name>finbook::ui::BetweenFitView</name>
    <message>
        <location filename="../ui/src/inbetween/between_fit_view.cpp" line="38"/>
        <source>Drag from a line of the first drawing to where it belongs on the second to pin it there; drag a pin to move it, right-click it to take it away.</source>
        <translation>最初の絵の線から二番目の絵の対応する場所へドラッグするとピンで留まります。ピンはドラッグで動かし、右クリックで外します。</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/between_fit_view.cpp" line="137"/>
        <source>No drawing to fit</source>
        <translation>合わせる絵がありません</translation>
    </message>
</context>
<context>
    <name>finbook::ui::BezierEditorDialog</name>
    <message>
        <location filename="../ui/src/camera/bezier_editor.cpp" line="117"/>
        <source>Camera Easing Curve</source>
        <translation>カメラのイージングカーブ</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/bezier_editor.cpp" line="124"/>
        <source>Ease</source>
        <translation>イーズ</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/bezier_editor.cpp" line="125"/>
        <source>Ease In</source>
        <translation>イーズイン</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/bezier_editor.cpp" line="126"/>
        <source>Ease Out</source>
        <translation>イーズアウト</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/bezier_editor.cpp" line="127"/>
        <source>Ease In and Out</source>
        <translation>イーズインとアウト</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/bezier_editor.cpp" line="128"/>
        <source>Overshoot</source>
        <translation>オーバーシュート</translation>
    </message>
</context>
<context>
    <name>finbook::ui::BoneTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/skeleton/tool_bone.h" line="40"/>
        <source>Bone</source>
        <translation>ボーン</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/skeleton/tool_bone.h" line="43"/>
        <source>build a skeleton and pose the drawing by its bones</source>
        <translation>骨格を作り、骨で絵にポーズをつける</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="55"/>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="168"/>
        <source>Build Skeleton</source>
        <translation>スケルトンを作成</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="56"/>
        <source>The object is posed with another deformer. Building a skeleton discards that pose. Build it anyway?</source>
        <translation>このオブジェクトには別の変形方法によるポーズが付いています。スケルトンを作成すると、そのポーズは破棄されます。作成しますか？</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="186"/>
        <source>Joined to %1. Shift-drag its root to join it elsewhere; right-click it to detach it.</source>
        <translation>%1 に接続しました。ルートを Shift キーを押しながらドラッグすると別の場所に接続し、右クリックで切り離します。</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="261"/>
        <source>Click on a visible, unlocked drawing to give it a skeleton.</source>
        <translation>表示されていてロックされていない絵をクリックすると、スケルトンを作成できます。</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="268"/>
        <source>Drag a joint to move it, click a bone to insert a joint; right-click a joint to delete it.</source>
        <translation>関節をドラッグで移動、ボーンをクリックで関節を挿入、関節を右クリックで削除します。</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="271"/>
        <source>Drag a bone to turn it, a joint to pull it, the root to move the object; press L over a joint to lock it; Shift-drag the root onto another part to join them.</source>
        <translation>ボーンをドラッグすると回転、関節をドラッグすると引っ張り、ルートをドラッグするとオブジェクトを移動します。関節の上で L キーを押すとロックします。ルートを Shift キーを押しながら別のパーツへドラッグすると接続します。</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="366"/>
        <source>Drop the root on a bone of another part to join them.</source>
        <translation>ルートを別のパーツのボーンにドロップすると接続します。</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone.cpp" line="374"/>
        <source>%1 hangs from this part already, so it cannot hang from it in turn.</source>
        <translation>%1 はすでにこのパーツにぶら下がっているため、逆にぶら下げることはできません。</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="115"/>
        <source>Edit Joints: drag a joint to move it, click a bone to insert a joint.</source>
        <translation>関節を編集：関節をドラッグで移動、ボーンをクリックで関節を挿入します。</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="130"/>
        <source>Reset the pose or apply it to the drawing before editing joints.</source>
        <translation>関節を編集する前に、ポーズをリセットするか絵に適用してください。</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="192"/>
        <source>Unlock Joint</source>
        <translation>関節のロックを解除</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="192"/>
        <source>Lock Joint</source>
        <translation>関節をロック</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="197"/>
        <source>Reset Bone Pose</source>
        <translation>ボーンのポーズをリセット</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="200"/>
        <source>Edit Joints</source>
        <translation>関節を編集</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="205"/>
        <source>Insert Joint Here</source>
        <translation>ここに関節を挿入</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="207"/>
        <source>Delete Joint</source>
        <translation>関節を削除</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="211"/>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="263"/>
        <source>Make Root Joint</source>
        <translation>ルート関節にする</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="220"/>
        <source>Detach from %1</source>
        <translation>%1 から切り離す</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="223"/>
        <source>Make Character Root</source>
        <translation>キャラクターのルートにする</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="224"/>
        <source>Join Overlapping Parts</source>
        <translation>重なるパーツを接続</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="275"/>
        <source>No part overlaps another part&apos;s skeleton.</source>
        <translation>他のパーツのスケルトンに重なるパーツはありません。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/skeleton/tool_bone_menu.cpp" line="279"/>
        <source>Joined %n part(s).</source>
        <translation>
            <numerusform>%n 個のパーツを接続しました。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::ui::BrushToolBar</name>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="16"/>
        <source>Brush</source>
        <translation>ブラシ</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="23"/>
        <source>Pressure</source>
        <translation>筆圧</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="37"/>
        <source>Width:</source>
        <translation>太さ:</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="42"/>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="44"/>
        <source>Smoothing:</source>
        <translation>スムージング:</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="47"/>
        <source>How much a stroke is smoothed when the pen lifts</source>
        <translation>ペンを離したときにストロークをどれだけ滑らかにするか</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="49"/>
        <source>Stabiliser:</source>
        <translation>手ぶれ補正:</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="52"/>
        <source>Off</source>
        <translation>オフ</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="53"/>
        <source>Steadies the line while you draw: the ink follows the pen on a string this long (4 screen pixels a step), so a shaky hand draws a smooth line. Off: the ink is under the pen.</source>
        <translation>描いている間の線を安定させます。インクはこの長さ（1 段階につき画面の 4 ピクセル）の糸で筆先に引かれるので、手が震えても滑らかな線になります。オフ: インクは筆先の真下に出ます。</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="58"/>
        <source>A tablet&apos;s pressure sets the line&apos;s width; off, every line has the full width</source>
        <translation>タブレットの筆圧で線の太さが決まります。オフにすると、どの線も最大の太さになります</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="116"/>
        <source>Pen colour %1</source>
        <translation>ペンの色: %1</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/brush_tool_bar.cpp" line="117"/>
        <source>Pen colour %1 (%2)</source>
        <translation>ペンの色 %1（%2）</translation>
    </message>
</context>
<context>
    <name>finbook::ui::CageActions</name>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="33"/>
        <source>&amp;Fit Cage</source>
        <translation>ケージをフィット(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="35"/>
        <source>Put a coarse cage around the current object in one step</source>
        <translation>現在のオブジェクトの周りに粗いケージを一度に配置</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="36"/>
        <source>Shift+C</source>
        <translation>Shift+C</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="37"/>
        <source>Edit Cage &amp;Shape</source>
        <translation>ケージの形状を編集(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="41"/>
        <source>Change the cage itself (move, add or delete corners) instead of posing with it</source>
        <translation>ケージでポーズを付ける代わりに、ケージ自体を変更（頂点を移動・追加・削除）</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="67"/>
        <source>Corners </source>
        <translation>頂点数 </translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="68"/>
        <source>About how many corners Fit Cage gives the cage</source>
        <translation>「ケージをフィット」で作成するケージのおおよその頂点数</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/cage_actions.cpp" line="82"/>
        <source>Choose an unlocked object with strokes to fit a cage to.</source>
        <translation>ケージを合わせる、ストロークのあるロックされていないオブジェクトを選んでください。</translation>
    </message>
</context>
<context>
    <name>finbook::ui::CageTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/cage/tool_cage.h" line="23"/>
        <source>Cage</source>
        <translation>ケージ</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/cage/tool_cage.h" line="26"/>
        <source>draw a cage around the drawing, then drag its corners to bend it</source>
        <translation>絵をケージで囲み、角をドラッグして曲げる</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/tool_cage.cpp" line="132"/>
        <source>Choose an object first: the cage goes around it.</source>
        <translation>先にオブジェクトを選んでください。ケージはその周りに配置されます。</translation>
    </message>
    <message>
        <location filename="../ui/src/cage/tool_cage.cpp" line="258"/>
        <source>A cage needs at least three corners.</source>
        <translation>ケージには少なくとも 3 つの頂点が必要です。</translation>
    </message>
</context>
<context>
    <name>finbook::ui::CameraTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/camera/tool_camera.h" line="30"/>
        <source>Camera</source>
        <translation>カメラ</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/camera/tool_camera.h" line="33"/>
        <source>frame the shot: move, zoom and turn the camera</source>
        <translation>ショットを決める: カメラを動かし、ズームし、回す</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="189"/>
        <source>Easing to the Next Key</source>
        <translation>次のキーへのイージング</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="193"/>
        <source>Linear</source>
        <translation>リニア</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="194"/>
        <source>Ease In</source>
        <translation>イーズイン</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="195"/>
        <source>Ease Out</source>
        <translation>イーズアウト</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="196"/>
        <source>Ease In and Out</source>
        <translation>イーズインとアウト</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="197"/>
        <source>Hold, Then Cut</source>
        <translation>保持してカット</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="208"/>
        <source>Bézier Curve...</source>
        <translation>ベジェ曲線...</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="214"/>
        <source>Delete Camera Key</source>
        <translation>カメラキーを削除</translation>
    </message>
    <message>
        <location filename="../ui/src/camera/tool_camera.cpp" line="217"/>
        <source>Reset Camera</source>
        <translation>カメラをリセット</translation>
    </message>
</context>
<context>
    <name>finbook::ui::CanvasWidget</name>
    <message>
        <location filename="../ui/src/canvas/canvas_widget.cpp" line="311"/>
        <source>The layer &quot;%1&quot; is locked: unlock it (Layer &gt; Lock Layer, or its padlock in the timeline) to draw on it.</source>
        <translation>レイヤー「%1」はロックされています。描くには、ロックを解除してください（レイヤー &gt; レイヤーをロック、またはタイムラインの錠前）。</translation>
    </message>
    <message>
        <location filename="../ui/src/canvas/canvas_widget.cpp" line="314"/>
        <source>The layer &quot;%1&quot; is hidden: show it (Layer &gt; Show Layer, or its eye in the timeline) to draw on it.</source>
        <translation>レイヤー「%1」は非表示です。描くには、表示してください（レイヤー &gt; レイヤーを表示、またはタイムラインの目のアイコン）。</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ColorButton</name>
    <message>
        <location filename="../ui/src/widgets/color_button.cpp" line="13"/>
        <source>Choose a colour</source>
        <translation>色を選択</translation>
    </message>
    <message>
        <location filename="../ui/src/widgets/color_button.cpp" line="31"/>
        <source>Choose Colour</source>
        <translation>色の選択</translation>
    </message>
</context>
<context>
    <name>finbook::ui::DeformActions</name>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="26"/>
        <source>&amp;Reset Pose</source>
        <translation>ポーズをリセット(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="30"/>
        <source>&amp;Apply Pose to Drawing</source>
        <translation>ポーズを絵に適用(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="29"/>
        <source>Move the current object&apos;s pins, cage corners or bones back to their rest positions</source>
        <translation>現在のオブジェクトのピン、ケージの頂点、またはボーンを元の位置に戻す</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="32"/>
        <source>Make the posed drawing the object&apos;s new strokes; the pins, cage or skeleton stay where they are</source>
        <translation>ポーズを付けた絵をオブジェクトの新しいストロークにする（ピン、ケージ、スケルトンはその位置のまま）</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="34"/>
        <source>Remo&amp;ve Rig</source>
        <translation>リグを削除(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="37"/>
        <source>Take the pins, the cage or the skeleton off the current object</source>
        <translation>現在のオブジェクトからピン、ケージ、またはスケルトンを外す</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="57"/>
        <source>The posed picture is now the object&apos;s picture: resampled once, it is a little softer. Undo brings back the original.</source>
        <translation>ポーズを付けた画像がオブジェクトの画像になりました。一度だけ再サンプリングしたため、少しぼやけます。元に戻すと元の画像に戻ります。</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/rig/deform_actions.cpp" line="74"/>
        <source>The pins fold the drawing: %n triangle(s) of its mesh turned over where the pins leave no room (View → Show Mesh shows them red)</source>
        <translation>
            <numerusform>ピンが絵を折り返しています。ピンの間に余地がないため、メッシュの三角形 %n 個が裏返っています（表示 → メッシュを表示 で赤く示されます）</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="79"/>
        <source>Preparing the deformation…</source>
        <translation>変形を準備しています…</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="89"/>
        <source>R&amp;igidity</source>
        <translation>剛性(&amp;I)</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="103"/>
        <source>Converged (Most Rigid)</source>
        <translation>収束まで（最も硬く）</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="104"/>
        <source>As in the Paper (Two Steps)</source>
        <translation>論文どおり（2 段階）</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="105"/>
        <source>Stiffer (+1 Pass)</source>
        <translation>より硬く（+1 パス）</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="106"/>
        <source>Stiffest (+3 Passes)</source>
        <translation>最も硬く（+3 パス）</translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="139"/>
        <source>Mesh density </source>
        <translation>メッシュ密度 </translation>
    </message>
    <message>
        <location filename="../ui/src/rig/deform_actions.cpp" line="140"/>
        <source>How fine the current object&apos;s deformation mesh is (1 = default)</source>
        <translation>現在のオブジェクトの変形メッシュの細かさ（1 = 標準）</translation>
    </message>
</context>
<context>
    <name>finbook::ui::DocumentSettingsDialog</name>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="26"/>
        <source>Start again after the last frame</source>
        <translation>最後のフレームの後、最初から再生する</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="30"/>
        <source>Document Settings</source>
        <translation>ドキュメント設定</translation>
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
        <translation>最後</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="50"/>
        <source>to</source>
        <translation>～</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="54"/>
        <source>&amp;Frame rate:</source>
        <translation>フレームレート(&amp;F):</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="55"/>
        <source>Canvas size:</source>
        <translation>キャンバスサイズ:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="56"/>
        <source>&amp;Background:</source>
        <translation>背景(&amp;B):</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="57"/>
        <source>Loop:</source>
        <translation>ループ:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="58"/>
        <source>Play frames:</source>
        <translation>再生するフレーム:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/document_settings_dialog.cpp" line="125"/>
        <source>Background Colour</source>
        <translation>背景色</translation>
    </message>
</context>
<context>
    <name>finbook::ui::EraserTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_eraser.h" line="29"/>
        <source>Eraser</source>
        <translation>消しゴム</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_eraser.h" line="30"/>
        <source>rub out parts of lines, or whole strokes</source>
        <translation>線の一部、または線ごと消す</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_eraser.cpp" line="160"/>
        <source>Erase</source>
        <translation>消去</translation>
    </message>
</context>
<context>
    <name>finbook::ui::EraserToolBar</name>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="11"/>
        <source>Eraser</source>
        <translation>消しゴム</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="13"/>
        <source>Cut Lines</source>
        <translation>線を切る</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="14"/>
        <source>Whole Strokes</source>
        <translation>ストローク全体</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="25"/>
        <source>Erase the part of a line under the eraser (the rest is split into pieces)</source>
        <translation>消しゴムの下の線の部分を消します（残りは分割されます）</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="28"/>
        <source>Erase every stroke the eraser touches (or hold Shift when you start rubbing)</source>
        <translation>消しゴムが触れたストロークを丸ごと消します（または消し始めるときに Shift キーを押したまま）</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="31"/>
        <source>Size:</source>
        <translation>サイズ:</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="35"/>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/eraser_tool_bar.cpp" line="36"/>
        <source>The eraser&apos;s diameter on the canvas</source>
        <translation>キャンバス上での消しゴムの直径</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ExportDialog</name>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="59"/>
        <location filename="../ui/src/export/export_dialog.cpp" line="340"/>
        <source>Export Animation</source>
        <translation>アニメーションの書き出し</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="67"/>
        <location filename="../ui/src/export/export_dialog.cpp" line="328"/>
        <source>untitled</source>
        <translation>無題</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="79"/>
        <source>Animated GIF</source>
        <translation>アニメーション GIF</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="80"/>
        <source>MP4 video (H.264)</source>
        <translation>MP4 動画（H.264）</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="81"/>
        <source>WebM video (VP9)</source>
        <translation>WebM 動画（VP9）</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="82"/>
        <source>Animated PNG (APNG)</source>
        <translation>アニメーション PNG（APNG）</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="83"/>
        <source>HTML flipbook (one file)</source>
        <translation>HTML パラパラ漫画（1 ファイル）</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="84"/>
        <source>Lottie animation (JSON), for web pages and apps</source>
        <translation>Lottie アニメーション (JSON)、ウェブページやアプリ向け</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="85"/>
        <source>dotLottie animation (compressed Lottie)</source>
        <translation>dotLottie アニメーション (圧縮した Lottie)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="86"/>
        <source>PNG images (a folder)</source>
        <translation>PNG 画像（フォルダー）</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="87"/>
        <source>SVG vector images (a folder)</source>
        <translation>SVG ベクター画像（フォルダー）</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="88"/>
        <source>3D model (OBJ), the current frame</source>
        <translation>3D モデル (OBJ)、現在のフレーム</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="89"/>
        <source>3D model (glTF binary), the current frame</source>
        <translation>Finbook: パラパラ漫画のアニメーションエディター。

  finbook [FILE]               FILE をエディターで開く
  finbook info FILE            FILE の概要を JSON で出力する
  finbook export FILE OUTDIR   すべてのフレームを OUTDIR/frame_0001.png ... に描き出す
  finbook export FILE OUT      OUT.gif、.mp4、.webm、.apng、.html に書き出す
  finbook export FILE OUT.obj --frame N   フレーム N を 3D モデル (OUT.obj、OUT.mtl) に書き出す
  finbook export FILE OUT.glb --frame N   フレーム N を 3D モデル (glTF バイナリ) に書き出す
  finbook export FILE... --format F --out-dir DIR   複数のファイルを書き出す
  finbook thumbnail FILE OUT.png SIZE   最初のフレームを最大 SIZE px の PNG に書き出す</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="93"/>
        <source>&amp;Browse...</source>
        <translation>参照(&amp;O)...</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="95"/>
        <source>Play range</source>
        <translation>再生範囲</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="96"/>
        <source>All frames</source>
        <translation>すべてのフレーム</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="97"/>
        <source>Frames</source>
        <translation>フレーム</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="112"/>
        <source>Document background</source>
        <translation>ドキュメントの背景</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="113"/>
        <source>Transparent</source>
        <translation>透明</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="114"/>
        <source>Colour</source>
        <translation>色</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="118"/>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="119"/>
        <source>Start again after the last frame</source>
        <translation>最後のフレームの後、最初から再生する</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="120"/>
        <source>One file per drawing, with an exposure sheet</source>
        <translation>絵ごとに 1 ファイル（タイムシート付き）</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="121"/>
        <source>Include refere&amp;nce</source>
        <translation>参照を含める(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="123"/>
        <source>Paint the reference picture or video under the drawing (not in SVG or 3D)</source>
        <translation>参照画像または参照動画を絵の下に描きます (SVG と 3D を除く)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="143"/>
        <source>to</source>
        <translation>～</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="158"/>
        <source>&amp;Format:</source>
        <translation>形式(&amp;F):</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="159"/>
        <source>&amp;Save to:</source>
        <translation>保存先(&amp;S):</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="160"/>
        <source>F&amp;rames:</source>
        <translation>フレーム(&amp;R):</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="161"/>
        <source>Sc&amp;ale:</source>
        <translation>倍率(&amp;A):</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="162"/>
        <source>&amp;Background:</source>
        <translation>背景(&amp;B):</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="163"/>
        <source>Frame ra&amp;te:</source>
        <translation>フレームレート(&amp;T):</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="164"/>
        <source>Loop:</source>
        <translation>ループ:</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="169"/>
        <source>&amp;Export</source>
        <translation>書き出し(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="170"/>
        <source>Cancel Export</source>
        <translation>書き出しをキャンセル</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="271"/>
        <source>%1 x %2 pixels</source>
        <translation>%1×%2 ピクセル</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="274"/>
        <source>A 3D model holds the current frame (%1) only: its objects inflated, in their fill colours, with a .mtl file beside it. The frames, scale, background and frame rate do not apply.</source>
        <translation>3D モデルに入るのは現在のフレーム (%1) だけです。オブジェクトを膨らませ、塗りの色を付け、隣に .mtl ファイルを置きます。フレーム範囲、倍率、背景、フレームレートは使いません。</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="279"/>
        <source>A 3D model holds the current frame (%1) only: its objects inflated, in their fill colours, all in one file. The frames, scale, background and frame rate do not apply.</source>
        <translation>3D モデルに入るのは現在のフレーム (%1) だけです。オブジェクトを膨らませ、塗りの色を付け、1 つのファイルにまとめます。フレーム範囲、倍率、背景、フレームレートは使いません。</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="284"/>
        <source>This format needs the ffmpeg program, which was not found; install it (on Debian: apt install ffmpeg) first.</source>
        <translation>この形式には ffmpeg プログラムが必要ですが、見つかりませんでした。先にインストールしてください（Debian の場合: apt install ffmpeg）。</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="289"/>
        <source>The video carries the soundtrack, trimmed to the frames exported.</source>
        <translation>動画には書き出すフレームに合わせて切り出したサウンドトラックが入ります。</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="291"/>
        <source>The page carries the soundtrack; it plays with the frames once the viewer presses Play.</source>
        <translation>ページにはサウンドトラックが入ります。閲覧者が再生を押すとフレームと一緒に再生されます。</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="293"/>
        <source>This format has no sound: the soundtrack is left out (MP4, WebM and HTML carry it).</source>
        <translation>この形式には音声がありません。サウンドトラックは含まれません(MP4、WebM、HTML には入ります)。</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="337"/>
        <source>Export to Folder</source>
        <translation>フォルダーに書き出す</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog.cpp" line="341"/>
        <source>%1 files (*.%2)</source>
        <translation>%1 ファイル (*.%2)</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="30"/>
        <source>Choose where to export the animation to.</source>
        <translation>アニメーションの書き出し先を選んでください。</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="56"/>
        <source>Exporting...</source>
        <translation>書き出しています...</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="68"/>
        <source>Cancelling...</source>
        <translation>キャンセルしています...</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/export/export_dialog_run.cpp" line="86"/>
        <source>Exported %n file(s) to %1</source>
        <translation>
            <numerusform>%n 個のファイルを %1 に書き出しました</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="99"/>
        <source>Export cancelled; nothing was written.</source>
        <translation>書き出しをキャンセルしました。何も書き込まれていません。</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="124"/>
        <source>&quot;%1&quot; already exists. Replace it?</source>
        <translation>「%1」はすでに存在します。置き換えますか？</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/export/export_dialog_run.cpp" line="125"/>
        <source>%n file(s) at the target already exist, such as &quot;%1&quot;. Replace them?</source>
        <translation>
            <numerusform>書き出し先には「%1」など %n 個のファイルがすでに存在します。置き換えますか？</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="128"/>
        <source>Replace Files?</source>
        <translation>ファイルを置き換えますか？</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="135"/>
        <source>Export Anyway?</source>
        <translation>それでも書き出しますか？</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="137"/>
        <source>It may take a long time and a lot of disk space. Export anyway?</source>
        <translation>長い時間と多くのディスク容量が必要になることがあります。それでも書き出しますか？</translation>
    </message>
    <message>
        <location filename="../ui/src/export/export_dialog_run.cpp" line="145"/>
        <source>Cannot Export</source>
        <translation>書き出せません</translation>
    </message>
</context>
<context>
    <name>finbook::ui::EyedropperTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_eyedropper.h" line="29"/>
        <source>Eyedropper</source>
        <translation>スポイト</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_eyedropper.h" line="32"/>
        <source>take a line&apos;s or a fill&apos;s colour for the pen</source>
        <translation>線や塗りの色をペンに取る</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_eyedropper.cpp" line="63"/>
        <source>Nothing here to take a colour from: click a line or a fill.</source>
        <translation>ここには色を取れるものがありません。線か塗りをクリックしてください。</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_eyedropper.cpp" line="70"/>
        <source>The pen takes the line&apos;s colour %1.</source>
        <translation>ペンは線の色 %1 になりました。</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_eyedropper.cpp" line="71"/>
        <source>The pen takes the fill&apos;s colour %1.</source>
        <translation>ペンは塗りの色 %1 になりました。</translation>
    </message>
</context>
<context>
    <name>finbook::ui::FillTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/fill/tool_fill.h" line="23"/>
        <source>Fill</source>
        <translation>塗りつぶし</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/fill/tool_fill.h" line="24"/>
        <source>fill an enclosed region with colour</source>
        <translation>囲まれた領域を色で塗る</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/tool_fill.cpp" line="70"/>
        <source>No closed region here: close the outline, or raise Close gaps</source>
        <translation>ここに閉じた領域はありません。輪郭を閉じるか「隙間を閉じる」を大きくしてください</translation>
    </message>
</context>
<context>
    <name>finbook::ui::FrameActions</name>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="13"/>
        <source>Insert Frame &amp;Before</source>
        <translation>前にフレームを挿入(&amp;B)</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="15"/>
        <source>&amp;Insert Frame After</source>
        <translation>後ろにフレームを挿入(&amp;I)</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="17"/>
        <source>&amp;Duplicate Frame</source>
        <translation>フレームを複製(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="19"/>
        <source>Generate In-be&amp;tweens…</source>
        <translation>中割りを生成(&amp;T)…</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="21"/>
        <source>Delete Fra&amp;me</source>
        <translation>フレームを削除(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="24"/>
        <source>Move Frame &amp;Left</source>
        <translation>フレームを左へ移動(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="26"/>
        <source>Move Frame &amp;Right</source>
        <translation>フレームを右へ移動(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="29"/>
        <source>Hold Lon&amp;ger</source>
        <translation>表示時間を延ばす(&amp;G)</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="31"/>
        <source>Hold &amp;Shorter</source>
        <translation>表示時間を縮める(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="34"/>
        <source>&amp;Previous Frame</source>
        <translation>前のフレーム(&amp;V)</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/frame_actions.cpp" line="37"/>
        <source>&amp;Next Frame</source>
        <translation>次のフレーム(&amp;N)</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/timeline/frame_actions.cpp" line="126"/>
        <source>Delete %n Frame(s)</source>
        <translation>
            <numerusform>%n 枚のフレームを削除</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::ui::HandTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_hand.h" line="17"/>
        <source>Hand</source>
        <translation>手のひら</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_hand.h" line="18"/>
        <source>drag the view</source>
        <translation>表示をドラッグで動かす</translation>
    </message>
</context>
<context>
    <name>finbook::ui::InbetweenDialog</name>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="63"/>
        <source>Generate In-betweens</source>
        <translation>中割りを生成</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="69"/>
        <source>Objects:</source>
        <translation>オブジェクト:</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="72"/>
        <source>Where the first drawing lands on the second (drag to pin):</source>
        <translation>最初の絵が二番目のどこに重なるか (ドラッグでピン留め):</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="199"/>
        <source>With these pins the drawings could not be fitted: %1</source>
        <translation>このピンでは絵を合わせられませんでした: %1</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="246"/>
        <source>&amp;Frames between the keys:</source>
        <translation>キーの間のフレーム数(&amp;F):</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="249"/>
        <source>Linear</source>
        <translation>等間隔</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="250"/>
        <source>Ease in (slow from the first key)</source>
        <translation>イーズイン（最初のキーからゆっくり）</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="251"/>
        <source>Ease out (slow into the second key)</source>
        <translation>イーズアウト（2 番目のキーへゆっくり）</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="252"/>
        <source>Ease in and out</source>
        <translation>イーズイン・アウト</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="253"/>
        <source>Favour…</source>
        <translation>詰め…</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="254"/>
        <source>&amp;Spacing:</source>
        <translation>間隔(&amp;S):</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="258"/>
        <source>Left favours the first key, right the second.</source>
        <translation>左にすると最初のキー側に、右にすると 2 番目のキー側に詰めます。</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="259"/>
        <source>F&amp;avour:</source>
        <translation>詰め(&amp;A):</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="262"/>
        <source>Move pins and cage corners along &amp;arcs</source>
        <translation>ピンとケージの頂点を弧に沿って移動(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="265"/>
        <source>A limb swung between the keys keeps its length. Unchecked, every target moves in a straight line.</source>
        <translation>キーの間で振られた手足は長さを保ちます。オフにすると、すべての対象が直線的に移動します。</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="268"/>
        <source>Carry &amp;different drawings onto each other</source>
        <translation>異なる絵を互いに運ぶ(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="272"/>
        <source>Where the two keys are separate drawings of an object, the first is fitted onto the second as rigidly as possible and carried there, fading into the second&apos;s lines at the end. Unchecked, the drawing switches over half way.</source>
        <translation>二つのキーが同じオブジェクトの別々の絵のとき、最初の絵をできるだけ剛体的に二番目に合わせて運び、最後に二番目の線へ溶け込ませます。オフにすると途中で絵が切り替わります。</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="424"/>
        <source>Making the in-betweens…</source>
        <translation>中割りを作っています…</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="138"/>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="303"/>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="344"/>
        <source>(unnamed)</source>
        <translation>（名前なし）</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="39"/>
        <source>Move Correspondence Pins</source>
        <translation>対応ピンを動かす</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="306"/>
        <source>%1: interpolated</source>
        <translation>%1: 補間</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="308"/>
        <source>%1: held from the first key (no pins, cage or skeleton)</source>
        <translation>%1: 最初のキーを保持（ピン、ケージ、スケルトンがありません）</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="310"/>
        <source>%1: held from the first key (its pins, cage or skeleton differ between the keys)</source>
        <translation>%1: 最初のキーを保持（キーの間でピン、ケージ、またはスケルトンが異なります）</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="314"/>
        <source>%1: only in the first key, held in the first half</source>
        <translation>%1: 最初のキーにのみ存在、前半で保持</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="316"/>
        <source>%1: only in the second key, held in the second half</source>
        <translation>%1: 2 番目のキーにのみ存在、後半で保持</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="318"/>
        <source>%1: carried from the first key&apos;s drawing to the second&apos;s</source>
        <translation>%1: 最初のキーの絵から二番目の絵へ運ばれます</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="328"/>
        <source>Select two different frames as keys.</source>
        <translation>キーとして異なる 2 つのフレームを選んでください。</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="341"/>
        <source>%1: could not be carried onto the second key&apos;s drawing, so it switches over half way. %2</source>
        <translation>%1: 二番目のキーの絵へ運べないため、途中で切り替わります。%2</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="180"/>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="347"/>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="393"/>
        <source>Fitting the drawings that differ…</source>
        <translation>異なる絵を合わせています…</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="348"/>
        <source>Posing the preview…</source>
        <translation>プレビューを計算中…</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="389"/>
        <source>The preview could not be posed: %1</source>
        <translation>プレビューのポーズを計算できませんでした: %1</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="395"/>
        <source>No object has matching pins or a matching cage in both keys: the in-betweens will only hold drawings.</source>
        <translation>両方のキーで一致するピンまたはケージを持つオブジェクトがありません。中割りでは絵が保持されるだけです。</translation>
    </message>
    <message>
        <location filename="../ui/src/inbetween/inbetween_dialog.cpp" line="397"/>
        <source>The canvas shows the middle in-between.</source>
        <translation>キャンバスには中央の中割りが表示されています。</translation>
    </message>
</context>
<context>
    <name>finbook::ui::LayerActions</name>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="15"/>
        <source>Layer %1</source>
        <translation>レイヤー %1</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="32"/>
        <source>&amp;New Layer</source>
        <translation>新しいレイヤー(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="39"/>
        <source>&amp;Duplicate Layer</source>
        <translation>レイヤーを複製(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="46"/>
        <source>De&amp;lete Layer</source>
        <translation>レイヤーを削除(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="57"/>
        <source>Move Layer &amp;Up</source>
        <translation>レイヤーを上へ(&amp;U)</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="59"/>
        <source>Move Layer D&amp;own</source>
        <translation>レイヤーを下へ(&amp;O)</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="66"/>
        <source>Layer &amp;Above</source>
        <translation>上のレイヤー(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="68"/>
        <source>Layer &amp;Below</source>
        <translation>下のレイヤー(&amp;B)</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="71"/>
        <source>&amp;Show Layer</source>
        <translation>レイヤーを表示(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="74"/>
        <source>Loc&amp;k Layer</source>
        <translation>レイヤーをロック(&amp;K)</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="77"/>
        <source>Layer &amp;Properties...</source>
        <translation>レイヤーのプロパティ(&amp;P)...</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="81"/>
        <source>&amp;Insert Time</source>
        <translation>時間を挿入(&amp;I)</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="83"/>
        <source>Delete &amp;Time</source>
        <translation>時間を削除(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="121"/>
        <location filename="../ui/src/layers/layer_sheet.cpp" line="398"/>
        <source>Lock Layer</source>
        <translation>レイヤーをロック</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="121"/>
        <location filename="../ui/src/layers/layer_sheet.cpp" line="398"/>
        <source>Unlock Layer</source>
        <translation>レイヤーのロックを解除</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="122"/>
        <location filename="../ui/src/layers/layer_sheet.cpp" line="393"/>
        <source>Show Layer</source>
        <translation>レイヤーを表示</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="122"/>
        <location filename="../ui/src/layers/layer_sheet.cpp" line="393"/>
        <source>Hide Layer</source>
        <translation>レイヤーを非表示</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_actions.cpp" line="134"/>
        <source>Change Layer Properties</source>
        <translation>レイヤーのプロパティを変更</translation>
    </message>
</context>
<context>
    <name>finbook::ui::LayerPropertiesDialog</name>
    <message>
        <location filename="../ui/src/layers/layer_properties_dialog.cpp" line="21"/>
        <source>Show its neighbouring drawings in the onion skin</source>
        <translation>前後の絵をオニオンスキンに表示</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_properties_dialog.cpp" line="23"/>
        <source>Layer Properties</source>
        <translation>レイヤーのプロパティ</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_properties_dialog.cpp" line="36"/>
        <source>How far behind the page the layer lies: at depth 1 the camera&apos;s pans and zooms move it half as much (a distant background), at 0 exactly as much, below 0 more (a foreground rushing past).</source>
        <translation>レイヤーが紙面からどれだけ奥にあるか：奥行き1ではカメラのパンやズームで半分だけ動き（遠い背景）、0ではそのまま、0未満ではより大きく動きます（手前を横切る前景）。</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_properties_dialog.cpp" line="42"/>
        <source>&amp;Name:</source>
        <translation>名前(&amp;N):</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_properties_dialog.cpp" line="43"/>
        <source>&amp;Opacity:</source>
        <translation>不透明度(&amp;O):</translation>
    </message>
    <message>
        <location filename="../ui/src/layers/layer_properties_dialog.cpp" line="44"/>
        <source>&amp;Depth:</source>
        <translation>奥行き(&amp;D):</translation>
    </message>
</context>
<context>
    <name>finbook::ui::LipSyncDialog</name>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="67"/>
        <source>&amp;Run</source>
        <translation>実行(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="68"/>
        <source>&amp;Import Timings...</source>
        <translation>タイミングを読み込む(&amp;I)...</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="73"/>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="241"/>
        <source>Lip Sync</source>
        <translation>リップシンク</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="76"/>
        <source>Optional: the words spoken, for a closer fit</source>
        <translation>任意：話している言葉（より正確に合わせるため）</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="93"/>
        <source>%1 (from frame %2)</source>
        <translation>%1（フレーム %2 から）</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="97"/>
        <source>Recognises English speech (PocketSphinx, US English). Other languages: import timings made elsewhere.</source>
        <translation>英語の発話を認識します（PocketSphinx、米国英語）。ほかの言語は、別のツールで作ったタイミングを読み込んでください。</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="99"/>
        <source>The speech models are not installed (Debian: pocketsphinx-en-us): the mouth follows the loudness only, closed, half open or open.</source>
        <translation>音声モデルがインストールされていません（Debian: pocketsphinx-en-us）。口は音量だけに従い、閉じる・半開き・開くのいずれかになります。</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="103"/>
        <source>Mouth:</source>
        <translation>口：</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="104"/>
        <source>%1 (%2 drawings)</source>
        <translation>%1（絵 %2 枚）</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="105"/>
        <source>(none)</source>
        <translation>（なし）</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="107"/>
        <source>&amp;Sound:</source>
        <translation>音声(&amp;S)：</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="108"/>
        <source>&amp;Dialogue:</source>
        <translation>台詞(&amp;D)：</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="120"/>
        <source>The animation has no sound: File &gt; Import Sound… first, or import timings made elsewhere.</source>
        <translation>アニメーションに音声がありません。先にファイル &gt; 音声を読み込む… を使うか、別のツールで作ったタイミングを読み込んでください。</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="125"/>
        <source>Import Lip Sync Timings</source>
        <translation>リップシンクのタイミングを読み込む</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="175"/>
        <source>Cancel</source>
        <translation>キャンセル</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="175"/>
        <source>Close</source>
        <translation>閉じる</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="193"/>
        <source>Listening…</source>
        <translation>聞き取り中…</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="211"/>
        <source>Cancelling…</source>
        <translation>取り消し中…</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="217"/>
        <source>Cancelled: nothing was changed.</source>
        <translation>取り消しました。何も変更していません。</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="221"/>
        <source>Nothing was changed.</source>
        <translation>何も変更していません。</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="224"/>
        <source>from the loudness (the speech models are not installed)</source>
        <translation>音量から（音声モデルがインストールされていません）</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="225"/>
        <source>from the recognised speech</source>
        <translation>認識した発話から</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="226"/>
        <source>from the speech and the dialogue</source>
        <translation>発話と台詞から</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="228"/>
        <source>spelt by rules, not found in the dictionary: %1</source>
        <translation>辞書になく規則で綴った語：%1</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="246"/>
        <source>Keyed the mouth on %n frame(s), %1.</source>
        <translation>
            <numerusform>%n フレームに口のキーを打ちました（%1）。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="248"/>
        <source>%n frame(s) of the mouth&apos;s layer hold no mouth and were left as they were.</source>
        <translation>
            <numerusform>口のレイヤーの %n フレームには口がないため、そのままにしました。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="262"/>
        <source>%1 was not imported: %2</source>
        <translation>%1 は読み込みませんでした：%2</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="268"/>
        <source>from %1</source>
        <translation>%1 から</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/lip_sync_dialog.cpp" line="316"/>
        <source>The clip holds no sound to follow.</source>
        <translation>クリップに従うべき音がありません。</translation>
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
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="218"/>
        <source>Show Dr&amp;awing</source>
        <translation>表示する絵(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="236"/>
        <source>Timeline</source>
        <translation>タイムライン</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="239"/>
        <source>Objects</source>
        <translation>オブジェクト</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="243"/>
        <source>Reference</source>
        <translation>参照</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="263"/>
        <source>&lt;opened document&gt;</source>
        <translation>&lt;開いたドキュメント&gt;</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="265"/>
        <source>Undo History</source>
        <translation>操作履歴</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="272"/>
        <source>Palette</source>
        <translation>パレット</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="298"/>
        <source>Rotation </source>
        <translation>回転 </translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="302"/>
        <source>The view&apos;s rotation: the drawing is not changed. Shift+Space-drag on the canvas turns it freely; 4 and 6 turn it by 15°, 5 resets it, Shift+M mirrors it.</source>
        <translation>表示の回転です。絵は変わりません。キャンバス上で Shift+Space ドラッグで自由に回転、4 と 6 で 15° ずつ回転、5 で元に戻し、Shift+M で左右反転します。</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="328"/>
        <source>The reference &quot;%1&quot; cannot be shown: %2</source>
        <translation>参照「%1」を表示できません: %2</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="337"/>
        <source>%1, %2 px</source>
        <translation>%1, %2 px</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="348"/>
        <source>Frame %1 / %2</source>
        <translation>フレーム %1 / %2</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="349"/>
        <source>%1 %</source>
        <translation>%1%</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="354"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="436"/>
        <source>Untitled</source>
        <translation>無題</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window.cpp" line="355"/>
        <source>%1[*] - Finbook</source>
        <translation>%1[*] - Finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_deform.cpp" line="36"/>
        <source>&amp;Deform</source>
        <translation>変形(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_deform.cpp" line="51"/>
        <source>&amp;Lip Sync...</source>
        <translation>リップシンク(&amp;L)...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_deform.cpp" line="52"/>
        <source>Key a mouth chart&apos;s drawings from the soundtrack</source>
        <translation>サウンドトラックから口形チャートの絵にキーを打つ</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_deform.cpp" line="74"/>
        <source>Preparing the deformation…</source>
        <translation>変形を準備しています…</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="38"/>
        <source>Finbook animations (*.finbook);;All files (*)</source>
        <translation>Finbook アニメーション (*.finbook);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="49"/>
        <source>Object</source>
        <translation>オブジェクト</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="84"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="139"/>
        <source>Cannot Open File</source>
        <translation>ファイルを開けません</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="174"/>
        <source>Cannot Save File</source>
        <translation>ファイルを保存できません</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="180"/>
        <source>Saved %1</source>
        <translation>%1 を保存しました</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/window/main_window_files.cpp" line="146"/>
        <source>Opened what was readable of %1 (%n problem(s) repaired); save it under a new name.</source>
        <translation>
            <numerusform>%1 の読み取れた部分を開きました（%n 件の問題を修復）。新しい名前で保存してください。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="102"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="107"/>
        <source>Cannot Open the Example</source>
        <translation>見本を開けません</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="112"/>
        <source>The example walk cycle: change it and save it as your own.</source>
        <translation>見本の歩きサイクルです。変更して自分のものとして保存できます。</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="230"/>
        <source>&amp;%1 %2</source>
        <translation>&amp;%1 %2</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="239"/>
        <source>No recent files</source>
        <translation>最近使ったファイルはありません</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="249"/>
        <source>Cannot Import Mesh</source>
        <translation>メッシュをインポートできません</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="253"/>
        <location filename="../ui/src/window/main_window_menus.cpp" line="117"/>
        <source>Import Mesh</source>
        <translation>メッシュのインポート</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="373"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="386"/>
        <source>Reading &quot;%1&quot;...</source>
        <translation>「%1」を読み込んでいます…</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="357"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="373"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="386"/>
        <location filename="../ui/src/window/main_window_menus.cpp" line="125"/>
        <source>Import Picture</source>
        <translation>画像を読み込む</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="337"/>
        <location filename="../ui/src/window/main_window_files.cpp" line="375"/>
        <source>Cannot Import Picture</source>
        <translation>画像を読み込めません</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="358"/>
        <source>&quot;%1&quot; stands on a flat background (%2). Make that colour transparent, so that the object is only what is drawn on it?</source>
        <translation>「%1」は単色の背景（%2）の上にあります。この色を透明にして、描かれている部分だけをオブジェクトにしますか？</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/window/main_window_files.cpp" line="388"/>
        <source>Imported &quot;%1&quot;: %n picture object(s).</source>
        <translation>
            <numerusform>「%1」を読み込みました：画像オブジェクト %n 個。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="398"/>
        <source>Pasted picture</source>
        <translation>貼り付けた画像</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="410"/>
        <source>Reading the pasted picture...</source>
        <translation>貼り付けた画像を読み込んでいます...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="411"/>
        <source>Pasted a picture as an object.</source>
        <translation>画像をオブジェクトとして貼り付けました。</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="424"/>
        <source>Damaged File</source>
        <translation>破損したファイル</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="425"/>
        <source>Open anyway shows what is still readable as a new, unsaved animation; the damaged file is not changed.</source>
        <translation>「このまま開く」を選ぶと、まだ読み取れる部分を未保存の新しいアニメーションとして表示します。破損したファイルは変更されません。</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="428"/>
        <source>Open Anyway</source>
        <translation>このまま開く</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="438"/>
        <source>Unsaved Changes</source>
        <translation>未保存の変更</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="439"/>
        <source>&quot;%1&quot; has changes that are not saved. Save them before going on?</source>
        <translation>「%1」には保存されていない変更があります。続ける前に保存しますか？</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="445"/>
        <source>Open Animation</source>
        <translation>アニメーションを開く</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="451"/>
        <source>Save Animation</source>
        <translation>アニメーションを保存</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="452"/>
        <source>untitled.finbook</source>
        <translation>無題.finbook</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="65"/>
        <source>File</source>
        <translation>ファイル</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="77"/>
        <source>&amp;File</source>
        <translation>ファイル(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="78"/>
        <source>&amp;New</source>
        <translation>新規(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="80"/>
        <source>&amp;Open...</source>
        <translation>開く(&amp;O)...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="82"/>
        <source>Open Exa&amp;mple</source>
        <translation>見本を開く(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="84"/>
        <source>&amp;Welcome...</source>
        <translation>ようこそ(&amp;W)...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="91"/>
        <source>Open &amp;Recent</source>
        <translation>最近使ったファイル(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="95"/>
        <source>&amp;Save</source>
        <translation>保存(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="97"/>
        <source>Save &amp;As...</source>
        <translation>名前を付けて保存(&amp;A)...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="101"/>
        <source>E&amp;xport...</source>
        <translation>書き出し(&amp;X)...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="114"/>
        <source>&amp;Import Mesh...</source>
        <translation>メッシュをインポート(&amp;I)...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="117"/>
        <source>OFF meshes (*.off)</source>
        <translation>OFF メッシュ (*.off)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="122"/>
        <source>Import &amp;Picture...</source>
        <translation>画像を読み込む(&amp;P)...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="126"/>
        <source>Pictures (*.png *.jpg *.jpeg *.webp *.tif *.tiff *.gif *.bmp *.ora);;OpenRaster stacks (*.ora);;All files (*)</source>
        <translation>画像 (*.png *.jpg *.jpeg *.webp *.tif *.tiff *.gif *.bmp *.ora);;OpenRaster スタック (*.ora);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="132"/>
        <source>Import Re&amp;ference...</source>
        <translation>参照を読み込む(&amp;F)...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="138"/>
        <source>Cannot Import Reference</source>
        <translation>参照を読み込めません</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="140"/>
        <source>&amp;Quit</source>
        <translation>終了(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="158"/>
        <source>&amp;Edit</source>
        <translation>編集(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="160"/>
        <source>&amp;Undo</source>
        <translation>元に戻す(&amp;U)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="164"/>
        <source>&amp;Redo</source>
        <translation>やり直す(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_files.cpp" line="410"/>
        <location filename="../ui/src/window/main_window_menus.cpp" line="174"/>
        <source>Paste</source>
        <translation>貼り付け</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="179"/>
        <source>Cu&amp;t</source>
        <translation>切り取り(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="186"/>
        <source>&amp;Copy</source>
        <translation>コピー(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="193"/>
        <source>&amp;Paste</source>
        <translation>貼り付け(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="215"/>
        <source>&amp;Delete</source>
        <translation>削除(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="222"/>
        <source>Select &amp;All</source>
        <translation>すべて選択(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="228"/>
        <source>Dese&amp;lect</source>
        <translation>選択を解除(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="235"/>
        <source>D&amp;ocument Settings...</source>
        <translation>ドキュメント設定(&amp;O)...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="238"/>
        <source>Pre&amp;ferences...</source>
        <translation>環境設定(&amp;F)...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="267"/>
        <source>&amp;View</source>
        <translation>表示(&amp;V)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="268"/>
        <source>Zoom &amp;In</source>
        <translation>ズームイン(&amp;I)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="270"/>
        <source>Zoom &amp;Out</source>
        <translation>ズームアウト(&amp;O)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="272"/>
        <source>&amp;Fit to Window</source>
        <translation>ウィンドウに合わせる(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="274"/>
        <source>&amp;Actual Size (100 %)</source>
        <translation>実際のサイズ (100%)(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="280"/>
        <source>Rotate View &amp;Left</source>
        <translation>表示を左に回転(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="282"/>
        <source>Rotate View &amp;Right</source>
        <translation>表示を右に回転(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="285"/>
        <source>R&amp;eset View Rotation</source>
        <translation>表示の回転をリセット(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="288"/>
        <source>Mirror Vie&amp;w</source>
        <translation>表示を左右反転(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="296"/>
        <source>O&amp;nion Skin</source>
        <translation>オニオンスキン(&amp;K)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="307"/>
        <source>Onion Skin &amp;Settings...</source>
        <translation>オニオンスキンの設定(&amp;S)...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="309"/>
        <source>Show &amp;Mesh</source>
        <translation>メッシュを表示(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="315"/>
        <source>&amp;Camera View</source>
        <translation>カメラビュー(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="321"/>
        <source>&amp;Dim Other Layers</source>
        <translation>他のレイヤーを薄く表示(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="328"/>
        <source>&amp;Panels</source>
        <translation>パネル(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="334"/>
        <source>F&amp;rame</source>
        <translation>フレーム(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="347"/>
        <source>&amp;Layer</source>
        <translation>レイヤー(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="354"/>
        <source>&amp;Object</source>
        <translation>オブジェクト(&amp;O)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="372"/>
        <source>&amp;Tools</source>
        <translation>ツール(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="375"/>
        <source>Tools</source>
        <translation>ツール</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="383"/>
        <source>&amp;Help</source>
        <translation>ヘルプ(&amp;H)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="385"/>
        <source>Finbook &amp;Manual</source>
        <translation>Finbook マニュアル(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="390"/>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>キーボードショートカット(&amp;K)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="392"/>
        <source>&amp;About Finbook</source>
        <translation>Finbook について(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="422"/>
        <source>Onion Skin</source>
        <translation>オニオンスキン</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="446"/>
        <source>About Finbook</source>
        <translation>Finbook について</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="447"/>
        <source>&lt;h3&gt;Finbook %1&lt;/h3&gt;&lt;p&gt;A flipbook animation editor: draw frame by frame, and bend drawings with pins.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Finbook %1&lt;/h3&gt;&lt;p&gt;パラパラ漫画のアニメーションエディターです。1 フレームずつ描いて、ピンで絵を曲げられます。&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="162"/>
        <location filename="../ui/src/window/main_window_toolbars.cpp" line="39"/>
        <source>Undo</source>
        <translation>元に戻す</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_menus.cpp" line="166"/>
        <location filename="../ui/src/window/main_window_toolbars.cpp" line="41"/>
        <source>Redo</source>
        <translation>やり直す</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_toolbars.cpp" line="45"/>
        <source>Apply Pose</source>
        <translation>ポーズを適用</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_toolbars.cpp" line="47"/>
        <source>Remove Rig</source>
        <translation>リグを削除</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_toolbars.cpp" line="49"/>
        <source>Reset</source>
        <translation>リセット</translation>
    </message>
    <message>
        <location filename="../ui/src/window/main_window_toolbars.cpp" line="51"/>
        <source>Shape</source>
        <translation>形状</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="30"/>
        <source>Reset &amp;Bone Pose</source>
        <translation>ボーンのポーズをリセット(&amp;B)</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="31"/>
        <source>Turn the bone selected with the Bone tool back to rest; the bones below it keep their bends</source>
        <translation>ボーンツールで選んだボーンを静止状態に戻します。その下のボーンは曲がりを保ちます</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="35"/>
        <source>&amp;Edit Joints</source>
        <translation>関節を編集(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="37"/>
        <source>With the Bone tool, move, insert and delete the joints of an unposed skeleton instead of posing it</source>
        <translation>ボーンツールで、ポーズを付ける代わりに、ポーズのないスケルトンの関節を移動・挿入・削除します</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="58"/>
        <source>Show S&amp;keleton</source>
        <translation>スケルトンを表示(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="64"/>
        <source>Skeleton</source>
        <translation>スケルトン</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="72"/>
        <source>S&amp;kinning</source>
        <translation>スキニング(&amp;K)</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="79"/>
        <source>&amp;Rigid (Bones Pin the Mesh)</source>
        <translation>剛体（ボーンがメッシュを固定）(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="81"/>
        <source>&amp;Linear Blend</source>
        <translation>線形ブレンド(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="83"/>
        <source>&amp;Cut-out (Limbs Turn over the Body)</source>
        <translation>切り絵（手足が胴体の上で回る）(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="115"/>
        <source>Rigid</source>
        <translation>リジッド</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="115"/>
        <source>Blend</source>
        <translation>ブレンド</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/main_window_skeleton.cpp" line="115"/>
        <source>Cut-out</source>
        <translation>切り絵</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/main_window_recovery.cpp" line="63"/>
        <source>Cannot Recover</source>
        <translation>復元できません</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/main_window_recovery.cpp" line="72"/>
        <source>Recovered %1 as it was at %2; save it to keep it.</source>
        <translation>%1 を %2 時点の状態に復元しました。残しておくには保存してください。</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/close_gap_box.cpp" line="27"/>
        <location filename="../ui/src/fill/close_gap_box.cpp" line="35"/>
        <source>Close gaps: automatic</source>
        <translation>隙間を閉じる: 自動</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/close_gap_box.cpp" line="34"/>
        <source>Close gaps: automatic (%1 px)</source>
        <translation>隙間を閉じる: 自動 (%1 px)</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="41"/>
        <source>Close gaps up to </source>
        <translation>隙間を閉じる: 最大 </translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="42"/>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="43"/>
        <source>Openings in an outline up to this wide still make a region the Fill tool can fill (0 = only closed outlines)</source>
        <translation>この幅までの輪郭の切れ目は、塗りつぶしツールで塗れる領域として扱います（0 = 閉じた輪郭のみ）</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="88"/>
        <source>Fill All Enclosed Re&amp;gions</source>
        <translation>閉じた領域をすべて塗る(&amp;G)</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="90"/>
        <source>Fill every closed region of the current object that has no fill, in the pen colour</source>
        <translation>現在のオブジェクトの塗られていない閉じた領域をすべてペンの色で塗ります</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="97"/>
        <source>The current object has no unfilled closed region</source>
        <translation>現在のオブジェクトに塗られていない閉じた領域はありません</translation>
    </message>
    <message>
        <location filename="../ui/src/fill/main_window_fill.cpp" line="109"/>
        <source>The colour the Fill tool fills with (the pen&apos;s)</source>
        <translation>塗りツールが塗る色（ペンの色）</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/main_window_shade.cpp" line="33"/>
        <source>Shading</source>
        <translation>陰影</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/main_window_lipsync.cpp" line="15"/>
        <source>Lip Sync</source>
        <translation>リップシンク</translation>
    </message>
    <message>
        <location filename="../ui/src/lipsync/main_window_lipsync.cpp" line="16"/>
        <source>Lip sync keys the drawings of a mouth chart. Make one with Object &gt; New Mouth Chart, redraw its mouths in your style, then come back here.</source>
        <translation>リップシンクは口形チャートの絵にキーを打ちます。オブジェクト &gt; 新規口形チャート で作り、口を自分の絵柄で描き直してから、ここに戻ってください。</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ManualBrowser</name>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="30"/>
        <location filename="../ui/src/help/manual_browser.cpp" line="99"/>
        <source>Contents</source>
        <translation>目次</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="31"/>
        <source>Getting Started: Draw, Bend, Play</source>
        <translation>はじめに: 描く、曲げる、再生する</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="32"/>
        <source>Drawing and the View</source>
        <translation>描画と表示</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="33"/>
        <source>Fills and Shading</source>
        <translation>塗りと陰影</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="34"/>
        <source>Pins</source>
        <translation>ピン</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="35"/>
        <source>Cages</source>
        <translation>ケージ</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="36"/>
        <source>Bones and Skeletons</source>
        <translation>ボーンとスケルトン</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="37"/>
        <source>In-betweens</source>
        <translation>中割り</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="38"/>
        <source>Timeline, Layers and Sound</source>
        <translation>タイムライン、レイヤー、サウンド</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="39"/>
        <source>Swapping Drawings and Lip Sync</source>
        <translation>絵の差し替えとリップシンク</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="40"/>
        <source>Camera</source>
        <translation>カメラ</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="41"/>
        <source>Pictures as Objects</source>
        <translation>オブジェクトとしての画像</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="42"/>
        <source>Reference Pictures and Video</source>
        <translation>参照画像と動画</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="43"/>
        <source>Exporting</source>
        <translation>書き出し</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="44"/>
        <source>Saving, Autosave and Recovery</source>
        <translation>保存、自動保存、復元</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="45"/>
        <source>The Command Line</source>
        <translation>コマンドライン</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="46"/>
        <source>Keyboard Shortcuts</source>
        <translation>キーボードショートカット</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="47"/>
        <source>Installing</source>
        <translation>インストール</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="84"/>
        <source>Finbook Manual</source>
        <translation>Finbook マニュアル</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="97"/>
        <source>Back</source>
        <translation>戻る</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="98"/>
        <source>Forward</source>
        <translation>進む</translation>
    </message>
    <message>
        <location filename="../ui/src/help/manual_browser.cpp" line="104"/>
        <source>Search the manual</source>
        <translation>マニュアルを検索</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ObjectActions</name>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="28"/>
        <source>&amp;New Object</source>
        <translation>新規オブジェクト(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="30"/>
        <source>&amp;Delete Object</source>
        <translation>オブジェクトを削除(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="31"/>
        <source>&amp;Merge Objects</source>
        <translation>オブジェクトを結合(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="34"/>
        <source>Move &amp;Selection to Object</source>
        <translation>選択範囲をオブジェクトへ移動(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="35"/>
        <source>Bring &amp;Forward</source>
        <translation>前面へ(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="37"/>
        <source>Send &amp;Backward</source>
        <translation>背面へ(&amp;B)</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="39"/>
        <source>&amp;Visible</source>
        <translation>表示(&amp;V)</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="40"/>
        <source>&amp;Locked</source>
        <translation>ロック(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="43"/>
        <source>New object above the current one</source>
        <translation>現在のオブジェクトの上に新しいオブジェクトを作成</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="44"/>
        <source>Merge the selected objects, or the current one into the one below</source>
        <translation>選択したオブジェクトを結合します。選択がなければ現在のオブジェクトを下のオブジェクトに結合します</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="45"/>
        <source>Move the selected strokes to another object</source>
        <translation>選択したストロークを別のオブジェクトへ移動</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="47"/>
        <source>New</source>
        <translation>新規</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="48"/>
        <source>Delete</source>
        <translation>削除</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="49"/>
        <source>Merge</source>
        <translation>結合</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="50"/>
        <source>Move To</source>
        <translation>移動先</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="119"/>
        <source>Object %1</source>
        <translation>オブジェクト %1</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="178"/>
        <source>Merge Objects</source>
        <translation>オブジェクトを結合</translation>
    </message>
    <message>
        <location filename="../ui/src/panels/object_actions.cpp" line="200"/>
        <source>Move Strokes to Object</source>
        <translation>ストロークをオブジェクトへ移動</translation>
    </message>
</context>
<context>
    <name>finbook::ui::OnionSkinEditor</name>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="14"/>
        <source>Show onion skin</source>
        <translation>オニオンスキンを表示</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="24"/>
        <source> %</source>
        <translation>%</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="27"/>
        <source>Frames before:</source>
        <translation>前のフレーム数:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="28"/>
        <source>Frames after:</source>
        <translation>後のフレーム数:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="29"/>
        <source>Opacity of the nearest frame:</source>
        <translation>最も近いフレームの不透明度:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="30"/>
        <source>Tint before:</source>
        <translation>前のフレームの色:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/onion_skin_editor.cpp" line="31"/>
        <source>Tint after:</source>
        <translation>後のフレームの色:</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PalettePanel</name>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="44"/>
        <source>&quot;%1&quot; is not a palette Finbook can read: %2.</source>
        <translation>&quot;%1&quot; は Finbook が読めるパレットではありません: %2。</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="72"/>
        <source>Swatch name</source>
        <translation>色見本の名前</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="73"/>
        <source>The chosen swatch&apos;s name: type and press Return to rename it</source>
        <translation>選んだ色見本の名前: 入力して Return で名前を変えます</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="89"/>
        <source>Add the pen&apos;s colour to the palette</source>
        <translation>ペンの色をパレットに追加</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="90"/>
        <source>Set</source>
        <translation>設定</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="91"/>
        <source>Give the chosen swatch the pen&apos;s colour</source>
        <translation>選んだ色見本をペンの色にする</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="93"/>
        <source>Move the chosen swatch one place earlier</source>
        <translation>選んだ色見本を 1 つ前へ</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="95"/>
        <source>Move the chosen swatch one place later</source>
        <translation>選んだ色見本を 1 つ後へ</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="97"/>
        <source>Delete the chosen swatch from the palette</source>
        <translation>選んだ色見本をパレットから削除</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="99"/>
        <source>Import, export, save and load palettes</source>
        <translation>パレットの読み込み、書き出し、保存、呼び出し</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="102"/>
        <source>&amp;Import GIMP Palette...</source>
        <translation>GIMP パレットを読み込む(&amp;I)...</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="103"/>
        <source>&amp;Export GIMP Palette...</source>
        <translation>GIMP パレットを書き出す(&amp;E)...</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="105"/>
        <source>&amp;Save as User Palette...</source>
        <translation>ユーザーパレットとして保存(&amp;S)...</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="106"/>
        <source>&amp;Load User Palette</source>
        <translation>ユーザーパレットを読み込む(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="109"/>
        <source>&amp;Reset to Finbook&apos;s Colours</source>
        <translation>Finbook の色に戻す(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="110"/>
        <source>Reset Palette</source>
        <translation>パレットをリセット</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="192"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="214"/>
        <source>A palette holds at most %1 colours.</source>
        <translation>パレットに入る色は最大 %1 色です。</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="219"/>
        <source>Add Swatch</source>
        <translation>色見本を追加</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="230"/>
        <source>Recolour Swatch</source>
        <translation>色見本の色を変更</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="240"/>
        <source>Delete Swatch</source>
        <translation>色見本を削除</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="251"/>
        <location filename="../ui/src/palette/palette_panel.cpp" line="288"/>
        <source>Move Swatch</source>
        <translation>色見本を移動</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="262"/>
        <source>Rename Swatch</source>
        <translation>色見本の名前を変更</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="338"/>
        <source>it is far larger than a palette</source>
        <translation>パレットにしては大きすぎます</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="347"/>
        <location filename="../ui/src/palette/palette_panel.cpp" line="410"/>
        <source>Import Palette</source>
        <translation>パレットを読み込む</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="354"/>
        <location filename="../ui/src/palette/palette_panel.cpp" line="376"/>
        <source>The palette could not be saved as &quot;%1&quot;: %2</source>
        <translation>パレットを &quot;%1&quot; として保存できませんでした: %2</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="368"/>
        <source>A user palette needs a name.</source>
        <translation>ユーザーパレットには名前が必要です。</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="370"/>
        <source>The folder for user palettes (%1) could not be made.</source>
        <translation>ユーザーパレットのフォルダ（%1）を作れませんでした。</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="391"/>
        <source>(no user palettes yet)</source>
        <translation>（ユーザーパレットはまだありません）</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="398"/>
        <source>Load Palette</source>
        <translation>パレットを読み込む</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="404"/>
        <source>Import GIMP Palette</source>
        <translation>GIMP パレットを読み込む</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="405"/>
        <source>GIMP palettes (*.gpl);;All files (*)</source>
        <translation>GIMP パレット (*.gpl);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="415"/>
        <source>Export GIMP Palette</source>
        <translation>GIMP パレットを書き出す</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="417"/>
        <source>GIMP palettes (*.gpl)</source>
        <translation>GIMP パレット (*.gpl)</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="424"/>
        <source>Export Palette</source>
        <translation>パレットを書き出す</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="426"/>
        <source>Palette saved as &quot;%1&quot;.</source>
        <translation>パレットを &quot;%1&quot; として保存しました。</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="433"/>
        <source>Save as User Palette</source>
        <translation>ユーザーパレットとして保存</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="433"/>
        <source>Name of the palette:</source>
        <translation>パレットの名前:</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="439"/>
        <source>Save Palette</source>
        <translation>パレットを保存</translation>
    </message>
    <message>
        <location filename="../ui/src/palette/palette_panel.cpp" line="441"/>
        <source>Saved as the user palette &quot;%1&quot;; Palette &gt; Load User Palette brings it into any drawing.</source>
        <translation>ユーザーパレット &quot;%1&quot; として保存しました。パレット &gt; ユーザーパレットを読み込む で、どの絵にも使えます。</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PenTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_pen.h" line="40"/>
        <source>Pen</source>
        <translation>ペン</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_pen.h" line="43"/>
        <source>draw lines; the pen&apos;s pressure sets their width</source>
        <translation>線を描く。筆圧で太さが変わる</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_pen.cpp" line="117"/>
        <source>Draw Stroke</source>
        <translation>ストロークを描画</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PinTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/pins/tool_pin.h" line="19"/>
        <source>Pin</source>
        <translation>ピン</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/pins/tool_pin.h" line="22"/>
        <source>pin points and drag them: the drawing bends as rigidly as it can</source>
        <translation>点をピンで留めてドラッグすると、絵ができるだけ形を保って曲がる</translation>
    </message>
    <message>
        <location filename="../ui/src/pins/tool_pin.cpp" line="162"/>
        <source>Click on a visible, unlocked drawing to pin it.</source>
        <translation>表示されていてロックされていない絵をクリックすると、ピンを置けます。</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PlaybackController</name>
    <message>
        <location filename="../ui/src/timeline/playback_controller.cpp" line="61"/>
        <location filename="../ui/src/timeline/playback_controller.cpp" line="226"/>
        <source>Pl&amp;ay</source>
        <translation>再生(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/playback_controller.cpp" line="65"/>
        <source>Play or pause the animation</source>
        <translation>アニメーションを再生または一時停止</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/playback_controller.cpp" line="73"/>
        <source>L&amp;oop</source>
        <translation>ループ再生(&amp;O)</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/playback_controller.cpp" line="77"/>
        <source>Start again at the end of the play range</source>
        <translation>再生範囲の最後まで来たら最初から再生</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/playback_controller.cpp" line="226"/>
        <source>P&amp;ause</source>
        <translation>一時停止(&amp;P)</translation>
    </message>
</context>
<context>
    <name>finbook::ui::PreferencesDialog</name>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="21"/>
        <source>Preferences</source>
        <translation>環境設定</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="25"/>
        <source>New Documents</source>
        <translation>新規ドキュメント</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="26"/>
        <source>Onion Skin</source>
        <translation>オニオンスキン</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="27"/>
        <source>Keyboard Shortcuts</source>
        <translation>キーボードショートカット</translation>
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
        <translation> 分</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="56"/>
        <source>Never</source>
        <translation>しない</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="57"/>
        <source>How often Finbook keeps a recovery copy of unsaved changes, offered at the next start if Finbook did not close normally.</source>
        <translation>Finbook が未保存の変更から復元用のコピーを作成する間隔です。Finbook が正常に終了しなかった場合、次回の起動時に復元を提案します。</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="61"/>
        <source>Frame rate:</source>
        <translation>フレームレート:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="62"/>
        <source>Canvas width:</source>
        <translation>キャンバスの幅:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="63"/>
        <source>Canvas height:</source>
        <translation>キャンバスの高さ:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="64"/>
        <source>Autosave every:</source>
        <translation>自動保存の間隔:</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="86"/>
        <source>Conflicting Shortcuts</source>
        <translation>ショートカットの競合</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/preferences_dialog.cpp" line="87"/>
        <source>Two or more actions share a shortcut. Change or clear the shortcuts marked in red, then press OK again.</source>
        <translation>複数の操作に同じショートカットが割り当てられています。赤で示されたショートカットを変更または消去してから、もう一度 OK を押してください。</translation>
    </message>
</context>
<context>
    <name>finbook::ui::RecoveryDialog</name>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="17"/>
        <source>Recover Unsaved Work</source>
        <translation>未保存の作業を復元</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="18"/>
        <source>Finbook did not close normally last time. It kept these copies of work that was not saved:</source>
        <translation>前回、Finbook は正常に終了しませんでした。保存されていなかった作業の次のコピーが残っています:</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="31"/>
        <source>&amp;Restore</source>
        <translation>復元(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="32"/>
        <source>&amp;Discard</source>
        <translation>破棄(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="33"/>
        <source>&amp;Later</source>
        <translation>後で(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="35"/>
        <source>Open the copy as an unsaved animation</source>
        <translation>コピーを未保存のアニメーションとして開く</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="36"/>
        <source>Delete the copy for good</source>
        <translation>コピーを完全に削除</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="37"/>
        <source>Keep the copies and ask again at the next start</source>
        <translation>コピーを残し、次回の起動時にもう一度確認</translation>
    </message>
    <message>
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="56"/>
        <source>Untitled</source>
        <translation>無題</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/recovery/recovery_dialog.cpp" line="58"/>
        <source>%1 — %2 — %n frame(s)</source>
        <translation>
            <numerusform>%1 — %2 — %n フレーム</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>finbook::ui::ReferencePanel</name>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="39"/>
        <source>&amp;Visible</source>
        <translation>表示(&amp;V)</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="40"/>
        <source>Loc&amp;ked</source>
        <translation>ロック(&amp;K)</translation>
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
        <translation>文書のレート</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="108"/>
        <source>Picture rate:</source>
        <translation>画像レート:</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="110"/>
        <source>Pictures per second of animation. At the document&apos;s rate every frame shows the next picture; a lower rate holds each picture for several frames.</source>
        <translation>アニメーション1秒あたりの画像数。ドキュメントのレートでは各フレームが次の画像を表示し、低いレートでは各画像を複数フレームにわたって表示します。</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="112"/>
        <source>Animation frames per second of video. At the document&apos;s rate the video plays in real time; a higher rate plays it slower, spreading each second over more frames.</source>
        <translation>ビデオ1秒あたりのアニメーションのフレーム数。ドキュメントのレートではビデオは実時間で再生され、高いレートでは各秒をより多くのフレームに広げてゆっくり再生します。</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="51"/>
        <source>&amp;Remove Reference</source>
        <translation>参照を削除(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="57"/>
        <source>Opacity:</source>
        <translation>不透明度:</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="58"/>
        <source>Centre X:</source>
        <translation>中心 X:</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="59"/>
        <source>Centre Y:</source>
        <translation>中心 Y:</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="60"/>
        <source>Scale:</source>
        <translation>拡大率:</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="61"/>
        <source>Rotation:</source>
        <translation>回転:</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="108"/>
        <source>Video rate:</source>
        <translation>動画のレート:</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="90"/>
        <source>No reference. File → Import Reference… puts a picture or a video under the drawing.</source>
        <translation>参照はありません。ファイル → 参照を読み込む… で画像や動画を絵の下に置けます。</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="167"/>
        <source>The reference could not be placed on the canvas.</source>
        <translation>参照をキャンバスに配置できませんでした。</translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="175"/>
        <location filename="../ui/src/reference/reference_panel.cpp" line="182"/>
        <source>Import Reference</source>
        <translation>参照を読み込む</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/reference/reference_panel.cpp" line="183"/>
        <source>“%1” is one of %n numbered pictures (%2 … %3). Import them all as a sequence, one picture per frame?</source>
        <translation>
            <numerusform>「%1」は %n 枚の連番画像（%2 … %3）の1枚です。すべてを連番として、1フレームに1枚ずつ読み込みますか？</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/reference/reference_panel.cpp" line="196"/>
        <source>Pictures and videos (*.png *.jpg *.jpeg *.webp *.bmp *.gif *.tif *.tiff *.mp4 *.m4v *.mov *.mkv *.webm *.avi);;All files (*)</source>
        <translation>画像と動画 (*.png *.jpg *.jpeg *.webp *.bmp *.gif *.tif *.tiff *.mp4 *.m4v *.mov *.mkv *.webm *.avi);;すべてのファイル (*)</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ReferenceTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/reference/tool_reference.h" line="21"/>
        <source>Move Reference</source>
        <translation>参照を移動</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/reference/tool_reference.h" line="24"/>
        <source>move, scale and turn the reference picture</source>
        <translation>参照画像を動かし、拡大縮小し、回す</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SelectTool</name>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_select.h" line="28"/>
        <source>Select</source>
        <translation>選択</translation>
    </message>
    <message>
        <location filename="../ui/include/finbook/ui/tools/tool_select.h" line="31"/>
        <source>lasso lines, then move, turn or scale them</source>
        <translation>投げ縄で線を選び、動かす・回す・拡大縮小する</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="400"/>
        <source>The strokes cannot be transformed that far.</source>
        <translation>ストロークをそこまで変形することはできません。</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="409"/>
        <source>Move Strokes</source>
        <translation>ストロークを移動</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="409"/>
        <source>Move Picture</source>
        <translation>画像を移動</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="410"/>
        <source>Rotate Strokes</source>
        <translation>ストロークを回転</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="410"/>
        <source>Rotate Picture</source>
        <translation>画像を回転</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="411"/>
        <source>Scale Strokes</source>
        <translation>ストロークを拡大・縮小</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="411"/>
        <source>Scale Picture</source>
        <translation>画像を拡大縮小</translation>
    </message>
    <message>
        <location filename="../ui/src/tools/tool_select.cpp" line="418"/>
        <source>The picture cannot be transformed that far.</source>
        <translation>画像をそこまで変形することはできません。</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ShadingPanel</name>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="25"/>
        <source>Flat</source>
        <translation>フラット</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="26"/>
        <source>Cel, two tones</source>
        <translation>セル、2 階調</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="27"/>
        <source>Cel, three tones</source>
        <translation>セル、3 階調</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="28"/>
        <source>Smooth</source>
        <translation>なめらか</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="29"/>
        <source>Shade the current object&apos;s fills from its rounded shape, in every frame where the object appears (objects of the same name)</source>
        <translation>現在のオブジェクトの塗りに、丸みを帯びた形から陰影を付けます。オブジェクトが現れるすべてのフレーム（同じ名前のオブジェクト）に適用されます</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="31"/>
        <source>Fills:</source>
        <translation>塗り:</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="32"/>
        <source>Rim light</source>
        <translation>リムライト</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="34"/>
        <source>A light edge on the side away from the light</source>
        <translation>光源と反対側の縁を明るくします</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="42"/>
        <source>Where the light comes from on screen: 0° from the right, 90° from above, 180° from the left</source>
        <translation>画面上で光の来る方向: 0° は右から、90° は上から、180° は左から</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="44"/>
        <source>Light direction:</source>
        <translation>光の方向:</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="50"/>
        <source>How high the light stands above the drawing: 0° grazes it, 90° shines from the viewer</source>
        <translation>光源の高さ: 0° は絵をかすめ、90° は見る人の側から照らします</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="52"/>
        <source>Light height:</source>
        <translation>光の高さ:</translation>
    </message>
    <message>
        <location filename="../ui/src/shade/shading_panel.cpp" line="89"/>
        <source>Fill regions of the current object with the Fill tool to shade them.</source>
        <translation>塗りつぶしツールで現在のオブジェクトの領域を塗ると、陰影を付けられます。</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ShortcutEditor</name>
    <message>
        <location filename="../ui/src/dialogs/shortcut_editor.cpp" line="31"/>
        <source>Action</source>
        <translation>操作</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcut_editor.cpp" line="31"/>
        <source>Shortcut</source>
        <translation>ショートカット</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcut_editor.cpp" line="31"/>
        <source>Alternative</source>
        <translation>代替</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcut_editor.cpp" line="72"/>
        <source>Restore Defaults</source>
        <translation>既定値に戻す</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcut_editor.cpp" line="132"/>
        <source>%1 is used by: %2</source>
        <translation>%1 の割り当て先: %2</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcut_editor.cpp" line="143"/>
        <source>Conflicting shortcuts:</source>
        <translation>競合しているショートカット:</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ShortcutsDialog</name>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="20"/>
        <source>Keyboard Shortcuts</source>
        <translation>キーボードショートカット</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="26"/>
        <source>Pan the view</source>
        <translation>表示をスクロール</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="26"/>
        <source>Space + drag, or middle button drag</source>
        <translation>Space + ドラッグ、または中ボタンでドラッグ</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="27"/>
        <source>Zoom about the cursor</source>
        <translation>カーソルを中心にズーム</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="27"/>
        <source>Mouse wheel</source>
        <translation>マウスホイール</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="31"/>
        <source>Action</source>
        <translation>操作</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="31"/>
        <source>Shortcut</source>
        <translation>ショートカット</translation>
    </message>
    <message>
        <location filename="../ui/src/dialogs/shortcuts_dialog.cpp" line="53"/>
        <source>Filter</source>
        <translation>フィルター</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SkeletonPanel</name>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="25"/>
        <source>Bone complexity</source>
        <translation>ボーンの細かさ</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="25"/>
        <source>Merge junctions</source>
        <translation>分岐点の統合</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="25"/>
        <source>Prune branches</source>
        <translation>枝の刈り込み</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="26"/>
        <source>Collapse short bones</source>
        <translation>短いボーンをまとめる</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="27"/>
        <source>Bones</source>
        <translation>ボーン</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="27"/>
        <source>Merge</source>
        <translation>結合</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="27"/>
        <source>Prune</source>
        <translation>刈り込み</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="27"/>
        <source>Collapse</source>
        <translation>まとめる</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="29"/>
        <source>More bones follow the shape more closely</source>
        <translation>ボーンが多いほど形状に忠実になります</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="30"/>
        <source>Junctions closer than this become one</source>
        <translation>これより近い分岐点は 1 つにまとめます</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="31"/>
        <source>Remove side branches shorter than this</source>
        <translation>これより短い側枝を削除します</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="32"/>
        <source>Collapse inner bones shorter than this into one joint</source>
        <translation>これより短い内側のボーンを 1 つのジョイントにまとめます</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="41"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../ui/src/skeleton/skeleton_panel.cpp" line="55"/>
        <source>Pick the Bone tool (K) and click an object to give it a skeleton.</source>
        <translation>ボーンツール（K）を選んでオブジェクトをクリックすると、スケルトンを作成できます。</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SoundController</name>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="42"/>
        <source>Import Soun&amp;d...</source>
        <translation>サウンドをインポート(&amp;D)...</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="44"/>
        <source>Add a sound file to the soundtrack, starting at the current frame</source>
        <translation>現在のフレームから始まるサウンドファイルをサウンドトラックに追加します</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="47"/>
        <source>Import Sound</source>
        <translation>サウンドのインポート</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="48"/>
        <source>Sound files (*.wav *.flac *.mp3 *.ogg *.oga *.opus *.m4a *.aac);;All files (*)</source>
        <translation>サウンドファイル (*.wav *.flac *.mp3 *.ogg *.oga *.opus *.m4a *.aac);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="74"/>
        <source>The sound &quot;%1&quot; cannot be played: %2</source>
        <translation>サウンド「%1」を再生できません: %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/src/sound/sound_controller.cpp" line="77"/>
        <source>%n sound(s) cannot be played; &quot;%1&quot;: %2</source>
        <translation>
            <numerusform>%n 個のサウンドを再生できません。「%1」: %2</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="100"/>
        <location filename="../ui/src/sound/sound_controller.cpp" line="140"/>
        <source>Cannot Import Sound</source>
        <translation>サウンドをインポートできません</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="100"/>
        <source>Cannot import &quot;%1&quot;: %2</source>
        <translation>「%1」をインポートできません: %2</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="103"/>
        <source>it is not a file.</source>
        <translation>ファイルではありません。</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="107"/>
        <source>it is larger than %1 MB.</source>
        <translation>%1 MB を超えています。</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="116"/>
        <source>Reading &quot;%1&quot;…</source>
        <translation>「%1」を読み込み中…</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="141"/>
        <source>Cannot import &quot;%1&quot;: %2 Nothing was changed.</source>
        <translation>「%1」をインポートできません: %2 何も変更されていません。</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="154"/>
        <location filename="../ui/src/sound/sound_controller.cpp" line="156"/>
        <source>Imported &quot;%1&quot; (%2 s).</source>
        <translation>「%1」をインポートしました(%2 秒)。</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="183"/>
        <source>Sound Volume</source>
        <translation>サウンドの音量</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_controller.cpp" line="183"/>
        <source>Volume of &quot;%1&quot; (%):</source>
        <translation>「%1」の音量 (%):</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SoundPlayer</name>
    <message>
        <location filename="../ui/src/sound/sound_player.cpp" line="69"/>
        <source>No audio output was found: playing without sound.</source>
        <translation>音声出力が見つかりません。音なしで再生します。</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_player.cpp" line="80"/>
        <source>The audio output failed: playing without sound.</source>
        <translation>音声出力に失敗しました。音なしで再生します。</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SoundRow</name>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="37"/>
        <source>The soundtrack: drag a sound to move it, right click for its volume</source>
        <translation>サウンドトラック: サウンドをドラッグして移動、右クリックで音量</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="133"/>
        <source>+%1 s after the last frame (not played)</source>
        <translation>最後のフレームの後に +%1 秒 (再生されません)</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="163"/>
        <source>No sound: File → Import Sound…</source>
        <translation>サウンドなし: ファイル → サウンドをインポート…</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="219"/>
        <source>%1 (cannot be played)</source>
        <translation>%1(再生できません)</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="221"/>
        <source>%1 (reading…)</source>
        <translation>%1(読み込み中…)</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="223"/>
        <source>%1 (muted)</source>
        <translation>%1(ミュート)</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="299"/>
        <source>&amp;Mute</source>
        <translation>ミュート(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="304"/>
        <source>&amp;Volume...</source>
        <translation>音量(&amp;V)...</translation>
    </message>
    <message>
        <location filename="../ui/src/sound/sound_row.cpp" line="306"/>
        <source>Delete &amp;Sound</source>
        <translation>サウンドを削除(&amp;S)</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SwapActions</name>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="24"/>
        <source>Make S&amp;wappable</source>
        <translation>差し替え可能にする(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="26"/>
        <source>New Mout&amp;h Chart</source>
        <translation>新規口形チャート(&amp;H)</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="29"/>
        <source>&amp;Previous Drawing</source>
        <translation>前の絵(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="32"/>
        <source>Ne&amp;xt Drawing</source>
        <translation>次の絵(&amp;X)</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="22"/>
        <source>Show Dr&amp;awing</source>
        <translation>表示する絵(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="35"/>
        <source>New Drawing in S&amp;et</source>
        <translation>セットに新しい絵(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="38"/>
        <source>D&amp;uplicate Drawing in Set</source>
        <translation>絵をセット内で複製(&amp;U)</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="40"/>
        <source>&amp;Rename Drawing...</source>
        <translation>絵の名前を変更(&amp;R)...</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="42"/>
        <source>Remove Drawing from Se&amp;t</source>
        <translation>絵をセットから削除(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="44"/>
        <source>Make Drawing &amp;Independent</source>
        <translation>絵を独立させる(&amp;I)</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="47"/>
        <source>Make the object&apos;s drawing the first of a set it swaps between, frame by frame (mouths, hands, blinks)</source>
        <translation>オブジェクトの絵を、フレームごとに差し替えるセットの最初の絵にする（口、手、まばたき）</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="50"/>
        <source>A new object showing the nine mouth shapes lip sync uses</source>
        <translation>リップシンクが使う 9 つの口の形を持つ新しいオブジェクト</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="52"/>
        <source>This frame keeps its drawing as its own: edits of it no longer reach the other frames</source>
        <translation>このフレームの絵を独自のものにします。以後の編集はほかのフレームに届きません</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="125"/>
        <source>(not swappable)</source>
        <translation>（差し替えできません）</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="129"/>
        <source>(unnamed)</source>
        <translation>（名前なし）</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="162"/>
        <source>&quot;%1&quot; is swappable: add drawings with Object &gt; New Drawing in Set, and pick one per frame with [ and ]</source>
        <translation>「%1」は差し替え可能です。オブジェクト &gt; セットに新しい絵 で絵を加え、フレームごとに [ と ] で選んでください</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="190"/>
        <source>New Mouth Chart</source>
        <translation>新規口形チャート</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="191"/>
        <location filename="../ui/src/swap/swap_actions.cpp" line="195"/>
        <source>Mouth</source>
        <translation>口</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="201"/>
        <source>A mouth chart on its own layer: nine mouth shapes to redraw in your style; [ and ] swap them, Deform &gt; Lip Sync keys them from the soundtrack</source>
        <translation>専用レイヤーに口形チャートを作りました。9 つの口を自分の絵柄で描き直してください。[ と ] で差し替え、変形 &gt; リップシンク でサウンドトラックからキーを打てます</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="226"/>
        <source>Rename Drawing</source>
        <translation>絵の名前を変更</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="226"/>
        <source>Name of the drawing:</source>
        <translation>絵の名前：</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_actions.cpp" line="273"/>
        <source>Drawing &quot;%1&quot;</source>
        <translation>絵「%1」</translation>
    </message>
</context>
<context>
    <name>finbook::ui::SwapPicker</name>
    <message>
        <location filename="../ui/src/swap/swap_picker.cpp" line="15"/>
        <source>Drawing:</source>
        <translation>絵：</translation>
    </message>
    <message>
        <location filename="../ui/src/swap/swap_picker.cpp" line="20"/>
        <source>The drawing this object shows in this frame ([ and ] step through them)</source>
        <translation>このフレームでこのオブジェクトが表示する絵（[ と ] で順に切り替え）</translation>
    </message>
</context>
<context>
    <name>finbook::ui::TimelineView</name>
    <message>
        <location filename="../ui/src/timeline/timeline_view.cpp" line="266"/>
        <source>Drag along the frame numbers to scrub through the animation</source>
        <translation>フレーム番号に沿ってドラッグするとアニメーションをスクラブします</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_view.cpp" line="268"/>
        <source>Click to show this frame; drag the picture to move the frame elsewhere; Ctrl- or Shift-click to pick several</source>
        <translation>クリックでこのフレームを表示、絵をドラッグでフレームを移動、Ctrl または Shift クリックで複数選択</translation>
    </message>
</context>
<context>
    <name>finbook::ui::TimelineWidget</name>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="91"/>
        <source>Onion Skin</source>
        <translation>オニオンスキン</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="92"/>
        <source>Show neighbouring frames faintly while drawing</source>
        <translation>描画中に前後のフレームを薄く表示</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="108"/>
        <source>Before:</source>
        <translation>前:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="109"/>
        <source>How many earlier frames the onion skin shows</source>
        <translation>オニオンスキンで表示する前のフレームの数</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="110"/>
        <source>After:</source>
        <translation>後:</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="111"/>
        <source>How many later frames the onion skin shows</source>
        <translation>オニオンスキンで表示する後のフレームの数</translation>
    </message>
    <message>
        <location filename="../ui/src/timeline/timeline_widget.cpp" line="142"/>
        <source>Frame %1 of %2 · %3 fps</source>
        <translation>フレーム %1 / %2 · %3 fps</translation>
    </message>
</context>
<context>
    <name>finbook::ui::ToolOptionsBar</name>
    <message>
        <location filename="../ui/src/window/tool_options_bar.cpp" line="11"/>
        <source>Tool Options</source>
        <translation>ツールオプション</translation>
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
        <translation>Finbook の起動時に毎回このページを表示</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="40"/>
        <source>Welcome to Finbook</source>
        <translation>Finbook へようこそ</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="50"/>
        <source>&amp;New Animation</source>
        <translation>新しいアニメーション(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="50"/>
        <source>Start an empty animation</source>
        <translation>空のアニメーションを始める</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="51"/>
        <source>&amp;Open...</source>
        <translation>開く(&amp;O)...</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="51"/>
        <source>Open a .finbook file</source>
        <translation>.finbook ファイルを開く</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="52"/>
        <source>Open the &amp;Example</source>
        <translation>見本を開く(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="53"/>
        <source>A short walk cycle drawn with Finbook, to look at and change</source>
        <translation>Finbook で描いた短い歩きサイクル。見たり変えたりできます</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="54"/>
        <source>Read the &amp;Manual</source>
        <translation>マニュアルを読む(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="55"/>
        <source>The Finbook Manual (F1 opens it at the tool in hand)</source>
        <translation>Finbook マニュアル（F1 で手に持っているツールのページを開きます）</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="63"/>
        <source>(no recent files yet)</source>
        <translation>（最近のファイルはまだありません）</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="70"/>
        <source>&lt;h2&gt;Draw — bend — play&lt;/h2&gt;&lt;p&gt;&lt;b&gt;1. Draw.&lt;/b&gt; Take the pen (&lt;b&gt;B&lt;/b&gt;) and draw a character; a tablet&apos;s pressure shapes the line. Close its outline loosely: small gaps close by themselves. Pick a colour in the Palette and click inside with the fill (&lt;b&gt;F&lt;/b&gt;).&lt;/p&gt;&lt;p&gt;&lt;b&gt;2. Bend.&lt;/b&gt; Instead of drawing the next frame again, duplicate the frame (&lt;b&gt;Ctrl+D&lt;/b&gt;) and bend the copy: click the drawing with the bone tool (&lt;b&gt;K&lt;/b&gt;) and drag a bone, or put pins on it (&lt;b&gt;P&lt;/b&gt;) and drag one; the rest follows as if drawn on rubber. The bent drawing is lines again: keep drawing on it.&lt;/p&gt;&lt;p&gt;&lt;b&gt;3. Play.&lt;/b&gt; Press &lt;b&gt;Return&lt;/b&gt; to play; Frame → In-betweens fills the frames between two poses. Onion skin (&lt;b&gt;O&lt;/b&gt;) shows the neighbours faintly. Save with &lt;b&gt;Ctrl+S&lt;/b&gt;, export a GIF, a video or a Lottie animation with File → Export.&lt;/p&gt;&lt;p&gt;&lt;a href=&quot;getting-started.md&quot;&gt;Read “Getting Started” in the manual&lt;/a&gt;, or press &lt;b&gt;F1&lt;/b&gt; at any time for the page of the tool in hand.&lt;/p&gt;</source>
        <translation>&lt;h2&gt;描く — 曲げる — 再生する&lt;/h2&gt;&lt;p&gt;&lt;b&gt;1. 描く。&lt;/b&gt;ペン（&lt;b&gt;B&lt;/b&gt;）でキャラクターを描きます。タブレットの筆圧が線の太さになります。輪郭はゆるく閉じれば十分で、小さな隙間は自動で閉じます。パレットで色を選び、塗り（&lt;b&gt;F&lt;/b&gt;）で内側をクリックします。&lt;/p&gt;&lt;p&gt;&lt;b&gt;2. 曲げる。&lt;/b&gt;次のフレームを描き直す代わりに、フレームを複製（&lt;b&gt;Ctrl+D&lt;/b&gt;）してコピーを曲げます。ボーンツール（&lt;b&gt;K&lt;/b&gt;）で絵をクリックしてボーンをドラッグするか、ピン（&lt;b&gt;P&lt;/b&gt;）を打って 1 本をドラッグすると、残りはゴムに描いたようについてきます。曲げた絵はまた線なので、そのまま描き足せます。&lt;/p&gt;&lt;p&gt;&lt;b&gt;3. 再生する。&lt;/b&gt;&lt;b&gt;Return&lt;/b&gt; で再生します。フレーム → 中割りで 2 つのポーズの間のフレームを作ります。オニオンスキン（&lt;b&gt;O&lt;/b&gt;）は前後のフレームを薄く表示します。&lt;b&gt;Ctrl+S&lt;/b&gt; で保存し、ファイル → 書き出しで GIF、動画、Lottie アニメーションを書き出します。&lt;/p&gt;&lt;p&gt;&lt;a href=&quot;getting-started.md&quot;&gt;マニュアルの「Getting Started」を読む&lt;/a&gt;。いつでも &lt;b&gt;F1&lt;/b&gt; で手に持っているツールのページを開けます。&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../ui/src/window/welcome_dialog.cpp" line="91"/>
        <source>Recent files:</source>
        <translation>最近のファイル:</translation>
    </message>
</context>
</TS>
