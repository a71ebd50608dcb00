<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>FitPanel</name>
    <message>
        <location filename="../ui/fit_panel.ui" line="9"/>
        <source>Select an object to fit its rotation to the sketched angular velocity.</source>
        <translation>选择一个对象，将其旋转拟合到草图绘制的角速度。</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="41"/>
        <source>Energy E = αW_T + βW_A</source>
        <translation>能量 E = αW_T + βW_A</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="45"/>
        <source>&amp;α (smoothness)</source>
        <translation>α（平滑度）(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="51"/>
        <source>Weight of the tangential acceleration W_T: larger is smoother, further from the sketch. The paper uses 0.001–0.005.</source>
        <translation>切向加速度 W_T 的权重：越大越平滑，但离草图越远。论文使用 0.001–0.005。</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="61"/>
        <source>&amp;β (follow the sketch)</source>
        <translation>β（贴合草图）(&amp;B)</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="67"/>
        <source>Weight of W_A, the deviation of the angular velocity from the sketch</source>
        <translation>W_A 的权重，即角速度与草图的偏差</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="77"/>
        <source>&amp;δ</source>
        <translation>δ(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="83"/>
        <source>The largest error accepted on a fragment of the window, measured in the target&apos;s own mean squared speed (F_n/S̄, in seconds); above it the fit inserts variable frames</source>
        <translation>窗口中每个片段允许的最大误差，以目标自身的均方速度衡量（F_n/S̄，单位为秒）；超过它时，拟合会插入可变帧</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="96"/>
        <source>Edited window</source>
        <translation>编辑窗口</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="100"/>
        <source>&amp;Whole sketch</source>
        <translation>整个草图(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="101"/>
        <source>Refit the span the sketch covers; clear to choose the window</source>
        <translation>重新拟合草图覆盖的区间；取消勾选以自行选择窗口</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="106"/>
        <source>&amp;Start</source>
        <translation>开始(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="112"/>
        <source>Where the refitted span begins</source>
        <translation>重新拟合区间的起点</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="115"/>
        <location filename="../ui/fit_panel.ui" line="130"/>
        <source> s</source>
        <translation> 秒</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="121"/>
        <source>E&amp;nd</source>
        <translation>结束(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="127"/>
        <source>Where the refitted span ends</source>
        <translation>重新拟合区间的终点</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="139"/>
        <source>Keyframes kept exactly</source>
        <translation>精确保持的关键帧</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="143"/>
        <source>A checked key keeps its orientation; the fit may turn a cleared one</source>
        <translation>勾选的关键帧保持其朝向；未勾选的关键帧可能被拟合旋转</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="149"/>
        <source>Time (s)</source>
        <translation>时间（秒）</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="150"/>
        <source>Constrained</source>
        <translation>约束</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="158"/>
        <source>Set &amp;physics target</source>
        <translation>设置物理目标(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="159"/>
        <source>Replace the sketch by the angular velocity of a free flight from where the motion is at the edit window&apos;s start; Fit then bends the motion toward it and keeps the constrained keys</source>
        <translation>用从编辑窗口起点的运动状态出发的自由飞行角速度替换草图；随后拟合会使运动趋向它，并保留受约束的关键帧</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="166"/>
        <source>Fit</source>
        <translation>拟合</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="167"/>
        <source>Fit the rotation to the sketch (Ctrl+F)</source>
        <translation>将旋转拟合到草图（Ctrl+F）</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="168"/>
        <source>Ctrl+F</source>
        <extracomment>A keyboard shortcut: keep it as it is. It stays translatable because uic then sets it after the button text, which would otherwise clear it.</extracomment>
        <translation>Ctrl+F</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="173"/>
        <source>&amp;Cancel</source>
        <translation>取消(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="174"/>
        <source>Stop the running fit; the motion stays as it is</source>
        <translation>停止正在进行的拟合；运动保持不变</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="179"/>
        <source>&amp;Remove fit</source>
        <translation>移除拟合(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="180"/>
        <source>Go back to the interpolation through the keys</source>
        <translation>回到经过关键帧的插值</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="187"/>
        <source>&amp;Live: refit while the sketch changes</source>
        <translation>实时：草图变化时重新拟合(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="188"/>
        <source>Refit at every change of the sketch, keys or settings; while drawing, the view previews the fit</source>
        <translation>草图、关键帧或设置每次变化时都重新拟合；绘制时视图会预览拟合结果</translation>
    </message>
</context>
<context>
    <name>InspectorWidget</name>
    <message>
        <location filename="../ui/inspector_widget.ui" line="9"/>
        <source>Select a keyframe on the timeline or in the viewport to inspect it.</source>
        <translation>在时间轴或视口中选择一个关键帧以查看它。</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="52"/>
        <source>Rotation Mode</source>
        <translation>旋转模式</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="56"/>
        <source>&amp;Keys store</source>
        <translation>关键帧存储(&amp;K)</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="62"/>
        <source>Quaternion keys store orientations; Euler keys store the three angles as typed, so 0° then 360° is a full turn, and interpolate them in the object&apos;s order</source>
        <translation>四元数关键帧存储朝向；欧拉关键帧按输入存储三个角度，因此 0° 到 360° 是完整一圈，并按物体的顺序插值</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="92"/>
        <source>Keyframe</source>
        <translation>关键帧</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="96"/>
        <source>&amp;Time (s)</source>
        <translation>时间（秒）(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="102"/>
        <source>Time in seconds</source>
        <translation>以秒为单位的时间</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="107"/>
        <source>&amp;Constrained: the fit keeps this key exactly</source>
        <translation>约束：拟合精确保持此关键帧(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="115"/>
        <source>Position</source>
        <translation>位置</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="137"/>
        <source>Position x</source>
        <translation>位置 x</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="142"/>
        <source>Position y</source>
        <translation>位置 y</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="147"/>
        <source>Position z</source>
        <translation>位置 z</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="155"/>
        <source>Quaternion</source>
        <translation>四元数</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="183"/>
        <source>Quaternion w</source>
        <translation>四元数 w</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="188"/>
        <source>Quaternion x</source>
        <translation>四元数 x</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="193"/>
        <source>Quaternion y</source>
        <translation>四元数 y</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="198"/>
        <source>Quaternion z</source>
        <translation>四元数 z</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="206"/>
        <source>Rotation matrix</source>
        <translation>旋转矩阵</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="210"/>
        <source>Matrix row 1, column 1</source>
        <translation>矩阵第 1 行第 1 列</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="215"/>
        <source>Matrix row 1, column 2</source>
        <translation>矩阵第 1 行第 2 列</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="220"/>
        <source>Matrix row 1, column 3</source>
        <translation>矩阵第 1 行第 3 列</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="225"/>
        <source>Matrix row 2, column 1</source>
        <translation>矩阵第 2 行第 1 列</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="230"/>
        <source>Matrix row 2, column 2</source>
        <translation>矩阵第 2 行第 2 列</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="235"/>
        <source>Matrix row 2, column 3</source>
        <translation>矩阵第 2 行第 3 列</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="240"/>
        <source>Matrix row 3, column 1</source>
        <translation>矩阵第 3 行第 1 列</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="245"/>
        <source>Matrix row 3, column 2</source>
        <translation>矩阵第 3 行第 2 列</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="250"/>
        <source>Matrix row 3, column 3</source>
        <translation>矩阵第 3 行第 3 列</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="258"/>
        <source>Axis-angle</source>
        <translation>轴角</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="262"/>
        <source>axis x</source>
        <translation>轴 x</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="268"/>
        <source>axis y</source>
        <translation>轴 y</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="274"/>
        <source>axis z</source>
        <translation>轴 z</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="280"/>
        <source>angle (°)</source>
        <translation>角度（°）</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="286"/>
        <source>Axis x</source>
        <translation>轴 x</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="291"/>
        <source>Axis y</source>
        <translation>轴 y</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="296"/>
        <source>Axis z</source>
        <translation>轴 z</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="301"/>
        <source>Angle in degrees</source>
        <translation>以度为单位的角度</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="309"/>
        <source>Euler angles</source>
        <translation>欧拉角</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="70"/>
        <source>&amp;Order</source>
        <translation>顺序(&amp;O)</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="76"/>
        <source>The axes the three angles turn about, first to last</source>
        <translation>三个角依次绕其旋转的轴，从第一个到最后一个</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="81"/>
        <source>Extrinsic angles turn about the fixed world axes; intrinsic ones about the axes as they have been turned so far</source>
        <translation>外旋角绕固定的世界坐标轴旋转；内旋角绕到此为止已转动的轴旋转</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="328"/>
        <source>Euler angle 1 in degrees</source>
        <translation>欧拉角 1，以度为单位</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="333"/>
        <source>Euler angle 2 in degrees</source>
        <translation>欧拉角 2，以度为单位</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="338"/>
        <source>Euler angle 3 in degrees</source>
        <translation>欧拉角 3，以度为单位</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <location filename="../ui/main_window.ui" line="18"/>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="19"/>
        <source>Open &amp;Recent</source>
        <translation>最近打开(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="20"/>
        <source>Open Sa&amp;mple</source>
        <translation>打开示例(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="34"/>
        <source>&amp;Edit</source>
        <translation>编辑(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="45"/>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="46"/>
        <source>&amp;Panels</source>
        <translation>面板(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="71"/>
        <source>&amp;Motion</source>
        <translation>运动(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="88"/>
        <source>&amp;Object</source>
        <translation>对象(&amp;O)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="89"/>
        <source>&amp;Add</source>
        <translation>添加(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="93"/>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="104"/>
        <source>File</source>
        <translation>文件</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="112"/>
        <source>Edit</source>
        <translation>编辑</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="117"/>
        <source>Playback</source>
        <translation>播放</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="129"/>
        <source>Inspector</source>
        <translation>检查器</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="141"/>
        <source>ScrewBender</source>
        <translation>ScrewBender</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="153"/>
        <source>Undo History</source>
        <translation>撤销历史</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="165"/>
        <source>Timeline</source>
        <translation>时间轴</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="177"/>
        <source>Smoothness</source>
        <translation>平滑度</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="189"/>
        <source>Angular Velocity Direction</source>
        <translation>角速度方向</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="201"/>
        <source>Fit</source>
        <translation>拟合</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="213"/>
        <source>Angular Speed</source>
        <translation>角速度大小</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="225"/>
        <source>Graph Editor</source>
        <translation>曲线编辑器</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="237"/>
        <source>&amp;New</source>
        <translation>新建(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="238"/>
        <source>Start a new, empty project</source>
        <translation>新建一个空项目</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="241"/>
        <source>&amp;Open…</source>
        <translation>打开(&amp;O)…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="242"/>
        <source>Open a Gyre project</source>
        <translation>打开 Gyre 项目</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="245"/>
        <source>&amp;Save</source>
        <translation>保存(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="246"/>
        <source>Save the project</source>
        <translation>保存项目</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="249"/>
        <source>Save &amp;As…</source>
        <translation>另存为(&amp;A)…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="250"/>
        <source>Save the project under a new name</source>
        <translation>以新名称保存项目</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="253"/>
        <source>&amp;Import Scene…</source>
        <translation>导入场景(&amp;I)…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="254"/>
        <source>Add the objects and motion of an FBX, glTF, Collada, OBJ, BVH or other scene file</source>
        <translation>添加 FBX、glTF、Collada、OBJ、BVH 或其他场景文件中的对象和运动</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="258"/>
        <source>&amp;Export Scene…</source>
        <translation>导出场景(&amp;E)…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="259"/>
        <source>Write the scene with its motion baked to glTF, Collada, FBX or OBJ</source>
        <translation>将场景及其烘焙后的运动写出为 glTF、Collada、FBX 或 OBJ</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="263"/>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="264"/>
        <source>Quit Gyre</source>
        <translation>退出 Gyre</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="268"/>
        <source>Undo &amp;History</source>
        <translation>撤销历史(&amp;H)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="269"/>
        <source>Show every step of the undo history</source>
        <translation>显示撤销历史中的每一步</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="273"/>
        <source>&amp;Preferences…</source>
        <translation>首选项(&amp;P)…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="274"/>
        <source>Choose the language Gyre speaks</source>
        <translation>选择 Gyre 使用的语言</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="280"/>
        <source>Original Motion as &amp;Ghost</source>
        <translation>以虚影显示原始运动(&amp;G)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="281"/>
        <source>Show the motion as it was when the project was opened or saved, faintly</source>
        <translation>淡淡地显示项目打开或保存时的运动</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="286"/>
        <source>Centre &amp;Trajectory</source>
        <translation>中心轨迹(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="287"/>
        <source>Show the path of the selected object&apos;s centre</source>
        <translation>显示所选对象中心的路径</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="292"/>
        <source>&amp;Control Poses</source>
        <translation>控制姿态(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="293"/>
        <source>Show the keyframe poses of the selected object in place</source>
        <translation>在原位显示所选对象的关键帧姿态</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="298"/>
        <source>&amp;Stroboscopic Trail</source>
        <translation>频闪轨迹(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="299"/>
        <source>Show many copies of the selected object along its subdivided motion</source>
        <translation>沿细分后的运动显示所选对象的多个副本</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="303"/>
        <source>Angular &amp;Momentum</source>
        <translation>角动量(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="304"/>
        <source>Show the selected object&apos;s angular momentum as an arrow from its centre of mass: in free flight it stands still</source>
        <translation>将所选物体的角动量显示为从质心出发的箭头：自由飞行时它静止不动</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="308"/>
        <source>Pri&amp;ncipal Axes</source>
        <translation>主轴(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="309"/>
        <source>Show the selected object&apos;s principal axes of inertia through its centre of mass</source>
        <translation>显示所选物体通过其质心的惯性主轴</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="312"/>
        <source>&amp;Frame Scene</source>
        <translation>显示整个场景(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="313"/>
        <source>Point the camera at the whole scene</source>
        <translation>将相机对准整个场景</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="317"/>
        <source>Frame &amp;Selected</source>
        <translation>显示所选对象(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="318"/>
        <source>Point the camera at the selected object</source>
        <translation>将相机对准所选对象</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="322"/>
        <source>&amp;Front View</source>
        <translation>前视图(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="323"/>
        <source>Look along +Y, Z up</source>
        <translation>沿 +Y 方向看,Z 朝上</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="327"/>
        <source>&amp;Back View</source>
        <translation>后视图(&amp;B)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="328"/>
        <source>Look along −Y, Z up</source>
        <translation>沿 −Y 方向看,Z 朝上</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="332"/>
        <source>&amp;Right View</source>
        <translation>右视图(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="333"/>
        <source>Look along −X, Z up</source>
        <translation>沿 −X 方向看,Z 朝上</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="337"/>
        <source>&amp;Left View</source>
        <translation>左视图(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="338"/>
        <source>Look along +X, Z up</source>
        <translation>沿 +X 方向看,Z 朝上</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="342"/>
        <source>&amp;Top View</source>
        <translation>顶视图(&amp;T)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="343"/>
        <source>Look down −Z, Y up</source>
        <translation>沿 −Z 向下看,Y 朝上</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="347"/>
        <source>Botto&amp;m View</source>
        <translation>底视图(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="348"/>
        <source>Look up +Z</source>
        <translation>沿 +Z 向上看</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="353"/>
        <source>&amp;Orthographic</source>
        <translation>正交投影(&amp;O)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="354"/>
        <source>Parallel projection instead of perspective</source>
        <translation>使用平行投影而非透视投影</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="359"/>
        <source>&amp;Wireframe</source>
        <translation>线框(&amp;W)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="360"/>
        <source>Draw the objects as the edges of their triangles</source>
        <translation>将对象绘制为其三角形的边</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="365"/>
        <source>&amp;X-Ray</source>
        <translation>X 射线(&amp;X)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="366"/>
        <source>Draw the objects see-through</source>
        <translation>将对象绘制为半透明</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="371"/>
        <source>&amp;Play</source>
        <translation>播放(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="372"/>
        <source>Play or pause the animation</source>
        <translation>播放或暂停动画</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="376"/>
        <source>Step &amp;Forward</source>
        <translation>前进一帧(&amp;F)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="377"/>
        <source>One frame later</source>
        <translation>后一帧</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="381"/>
        <source>Step &amp;Backward</source>
        <translation>后退一帧(&amp;B)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="382"/>
        <source>One frame earlier</source>
        <translation>前一帧</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="386"/>
        <source>Go to &amp;Start</source>
        <translation>转到开头(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="387"/>
        <source>Go to the first frame</source>
        <translation>转到第一帧</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="391"/>
        <source>Go to &amp;End</source>
        <translation>转到结尾(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="392"/>
        <source>Go to the last frame</source>
        <translation>转到最后一帧</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="398"/>
        <source>&amp;Loop</source>
        <translation>循环(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="399"/>
        <source>Start again from the beginning at the end</source>
        <translation>到结尾时从头重新开始</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="402"/>
        <source>&amp;Add Keyframe</source>
        <translation>添加关键帧(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="403"/>
        <source>Key every selected object&apos;s pose at the current time</source>
        <translation>在当前时间为每个所选物体的姿势设置关键帧</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="408"/>
        <source>Delete the selected keyframes</source>
        <translation>删除所选关键帧</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="407"/>
        <source>&amp;Delete Keyframe</source>
        <translation>删除关键帧(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="414"/>
        <source>&amp;Constrain Keyframe</source>
        <translation>约束关键帧(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="415"/>
        <source>Keep the selected keyframe exactly when fitting, or free it</source>
        <translation>拟合时精确保持所选关键帧，或将其释放</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="419"/>
        <source>&amp;Euler Filter</source>
        <translation>欧拉滤波器(&amp;E)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="420"/>
        <source>Make the selected object&apos;s keys continuous: each key&apos;s quaternion in the hemisphere of the key before</source>
        <translation>使所选对象的关键帧连续：每个关键帧的四元数位于前一关键帧的半球中</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="423"/>
        <source>&amp;Next Flight Solution</source>
        <translation>下一个飞行解(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="424"/>
        <source>Fly the current span of a ballistic track by its next free flight, by energy</source>
        <translation>让弹道轨迹的当前区间按能量顺序采用下一个自由飞行</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="427"/>
        <source>P&amp;revious Flight Solution</source>
        <translation>上一个飞行解(&amp;R)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="428"/>
        <source>Fly the current span of a ballistic track by its previous free flight, by energy</source>
        <translation>让弹道轨迹的当前区间按能量顺序采用上一个自由飞行</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="431"/>
        <source>&amp;Copy</source>
        <translation>复制(&amp;C)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="432"/>
        <source>Copy the selected keys, or with none selected the selected object&apos;s pose</source>
        <translation>复制所选关键帧；若未选关键帧，则复制所选物体的姿势</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="436"/>
        <source>&amp;Paste</source>
        <translation>粘贴(&amp;P)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="437"/>
        <source>Paste copied keys or a pose at the current time on the selected objects</source>
        <translation>在当前时间将复制的关键帧或姿势粘贴到所选物体上</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="441"/>
        <source>Select &amp;All Keys</source>
        <translation>选择全部关键帧(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="442"/>
        <source>Select every key of the selected object</source>
        <translation>选择所选物体的每个关键帧</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="446"/>
        <source>Select &amp;No Keys</source>
        <translation>取消选择关键帧(&amp;N)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="447"/>
        <source>Deselect every key</source>
        <translation>取消选择所有关键帧</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="451"/>
        <source>&amp;About Gyre</source>
        <translation>关于 Gyre(&amp;A)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="452"/>
        <source>Version, licence and the libraries Gyre is built on</source>
        <translation>版本、许可证以及 Gyre 所基于的库</translation>
    </message>
</context>
<context>
    <name>PreferencesDialog</name>
    <message>
        <location filename="../ui/preferences_dialog.ui" line="6"/>
        <source>Preferences</source>
        <translation>首选项</translation>
    </message>
    <message>
        <location filename="../ui/preferences_dialog.ui" line="12"/>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/preferences_dialog.ui" line="18"/>
        <source>The language of Gyre&apos;s menus, panels and messages</source>
        <translation>Gyre 的菜单、面板和消息所用的语言</translation>
    </message>
    <message>
        <location filename="../ui/preferences_dialog.ui" line="23"/>
        <source>The language changes when Gyre next starts.</source>
        <translation>语言将在 Gyre 下次启动时更改。</translation>
    </message>
</context>
<context>
    <name>ScrewBenderPanel</name>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="9"/>
        <source>Select an object to choose how its track is interpolated.</source>
        <translation>选择一个对象以设置其轨道的插值方式。</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="41"/>
        <source>Interpolation</source>
        <translation>插值</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="45"/>
        <source>&amp;Method</source>
        <translation>方法(&amp;M)</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="51"/>
        <source>How the track&apos;s orientation is interpolated between its keyframes</source>
        <translation>轨道的朝向在关键帧之间如何插值</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="59"/>
        <source>Subdivision</source>
        <translation>细分</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="63"/>
        <source>Used when the method is screw motion.</source>
        <translation>当方法为螺旋运动时使用。</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="69"/>
        <source>&amp;Scheme</source>
        <translation>方案(&amp;S)</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="75"/>
        <source>The Split&amp;Tweak rule that smooths the polyscrew at each level</source>
        <translation>在每一层平滑多段螺旋的 Split&amp;Tweak 规则</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="80"/>
        <source>&amp;Levels</source>
        <translation>层数(&amp;L)</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="86"/>
        <source>Each level doubles the poses</source>
        <translation>每一层使姿态数加倍</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="92"/>
        <source>Sequence</source>
        <translation>序列</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="99"/>
        <source>C&amp;yclic</source>
        <translation>循环(&amp;Y)</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="100"/>
        <source>The last keyframe joins the first: a closed loop</source>
        <translation>最后一个关键帧连接到第一个：闭合循环</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="105"/>
        <source>&amp;Open</source>
        <translation>开放(&amp;O)</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="106"/>
        <source>The motion starts at the first keyframe and ends at the last</source>
        <translation>运动从第一个关键帧开始，到最后一个关键帧结束</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="113"/>
        <source>&amp;Decoupled, for comparison</source>
        <translation>解耦，用于比较(&amp;D)</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="114"/>
        <source>The alternative the paper compares against: orientations by slerp, positions by the linear scheme, each subdivided on its own</source>
        <translation>论文用作对比的方案：朝向用 slerp，位置用线性方案，各自单独细分</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="119"/>
        <source>Poses</source>
        <translation>姿态</translation>
    </message>
</context>
<context>
    <name>gyre::FileError</name>
    <message>
        <location filename="../src/model/project_file.cpp" line="355"/>
        <source>these %1 keys bring the file past the %2 keys a project may hold</source>
        <translation>加上这 %1 个关键帧，文件超出项目可容纳的 %2 个关键帧</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="617"/>
        <source>these %1 times bring the file past the %2 times a project may hold</source>
        <translation>加上这 %1 个时间，文件超出项目可容纳的 %2 个时间</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="358"/>
        <source>the file has no time lists</source>
        <translation>文件没有时间列表</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="226"/>
        <source>is larger than 1 GiB, the most a project file may hold</source>
        <translation>大于 1 GiB，超出项目文件的上限</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="362"/>
        <source>time list %1 holds %2 times for %3 keys</source>
        <translation>时间列表 %1 有 %2 个时间，却对应 %3 个关键帧</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="591"/>
        <source>a version %1 file starts with &quot;%2&quot; and its version in binary, not with JSON text</source>
        <translation>版本 %1 的文件以“%2”及二进制的版本号开头，而不是 JSON 文本</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="680"/>
        <source>the file ends inside its first %1 bytes</source>
        <translation>文件在其前 %1 个字节内就结束了</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="685"/>
        <source>a version %1 file is JSON text, not binary</source>
        <translation>版本 %1 的文件是 JSON 文本，不是二进制</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="689"/>
        <source>%1 bytes; a header may hold at most %2</source>
        <translation>%1 字节；文件头最多 %2 字节</translation>
    </message>
    <message>
        <location filename="../src/model/project_blocks.cpp" line="139"/>
        <source>%1 is neither 0 nor 1</source>
        <translation>%1 既不是 0 也不是 1</translation>
    </message>
    <message>
        <location filename="../src/model/project_blocks.cpp" line="273"/>
        <source>its block needs %1 bytes; the file has %2 left</source>
        <translation>其数据块需要 %1 字节；文件只剩 %2 字节</translation>
    </message>
    <message>
        <location filename="../src/model/project_blocks.cpp" line="279"/>
        <source>the file ends %1 bytes into its block of %2</source>
        <translation>文件在其 %2 字节的数据块中第 %1 字节处结束</translation>
    </message>
    <message>
        <location filename="../src/model/project_blocks.cpp" line="289"/>
        <source>the file goes on after its last block</source>
        <translation>文件在最后一个数据块之后仍有内容</translation>
    </message>
    <message>
        <location filename="../src/model/project_blocks.cpp" line="295"/>
        <source>the writer has no block for it</source>
        <translation>写入程序没有它的数据块</translation>
    </message>
    <message>
        <location filename="../src/model/project_blocks.cpp" line="298"/>
        <source>its block holds %1 bytes, not %2</source>
        <translation>其数据块有 %1 字节，而不是 %2</translation>
    </message>
    <message>
        <location filename="../src/model/output_target.cpp" line="34"/>
        <source>cannot write to standard output: %1</source>
        <translation>无法写入标准输出：%1</translation>
    </message>
    <message>
        <location filename="../src/model/output_target.cpp" line="73"/>
        <location filename="../src/jobs/autosave.cpp" line="38"/>
        <source>cannot write: %1</source>
        <translation>无法写入：%1</translation>
    </message>
    <message>
        <location filename="../src/jobs/autosave.cpp" line="83"/>
        <source>cannot create the autosave directory</source>
        <translation>无法创建自动保存目录</translation>
    </message>
    <message>
        <location filename="../src/jobs/autosave.cpp" line="91"/>
        <source>cannot take the autosave lock</source>
        <translation>无法获取自动保存锁</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="168"/>
        <source>unknown value &quot;%1&quot;; expected one of %2</source>
        <translation>未知的值“%1”；应为以下之一：%2</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="263"/>
        <source>%1 bytes are not a whole number of %2-byte items</source>
        <translation>%1 字节不是 %2 字节条目的整数倍</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="315"/>
        <source>a skin has 1 to %1 joints</source>
        <translation>蒙皮有 1 到 %1 个关节</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="341"/>
        <location filename="../src/model/project_blocks.cpp" line="146"/>
        <source>the angles are not finite</source>
        <translation>角度不是有限数</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="392"/>
        <location filename="../src/model/value_checks.cpp" line="156"/>
        <source>a stroke needs at least one point</source>
        <translation>笔画至少需要一个点</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="394"/>
        <source>%1 times for %2 points; give none or one per point</source>
        <translation>%1 个时间对应 %2 个点；请不给时间或每个点给一个</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="421"/>
        <source>these %1 control points bring the file past the %2 keys a project may hold</source>
        <translation>加上这 %1 个控制点，文件超出项目可容纳的 %2 个关键帧</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="461"/>
        <location filename="../src/model/value_checks.cpp" line="207"/>
        <source>keys to restore without an applied fit</source>
        <translation>有待恢复的关键帧，却没有已应用的拟合</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="472"/>
        <source>an object in Euler rotation mode interpolates euler or euler-cubic</source>
        <translation>欧拉旋转模式的物体使用 euler 或 euler-cubic 插值</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="478"/>
        <source>an object in Euler rotation mode needs the angles of every key</source>
        <translation>欧拉旋转模式的物体需要每个关键帧的角度</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="479"/>
        <source>angles on an object in quaternion rotation mode</source>
        <translation>四元数旋转模式的物体带有角度</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="481"/>
        <source>the angles do not give the key&apos;s orientation</source>
        <translation>角度与关键帧的朝向不符</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="504"/>
        <source>the file has no meshes</source>
        <translation>文件中没有网格</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="539"/>
        <source>%1 is also the id of objects[%2]</source>
        <translation>%1 也是 objects[%2] 的 ID</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="542"/>
        <location filename="../src/model/project_file.cpp" line="630"/>
        <source>no object has id %1</source>
        <translation>没有 ID 为 %1 的对象</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="551"/>
        <source>object %1 is its own ancestor</source>
        <translation>对象 %1 是它自己的祖先</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="564"/>
        <source>object %1 comes after it in the file; parents come before their children</source>
        <translation>对象 %1 在文件中位于它之后；父对象须在子对象之前</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="585"/>
        <source>expected &quot;%1&quot;, found &quot;%2&quot;; this is not a Gyre project</source>
        <translation>应为“%1”，实际为“%2”；这不是 Gyre 项目</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="765"/>
        <source>not saved, because its header (the objects&apos; names and settings, the sketches&apos; strokes) would hold %1 bytes, more than the %2 a project may hold</source>
        <translation>未保存，因为其文件头（对象的名称和设置、草图的笔画）将有 %1 字节，超过项目可容纳的 %2 字节</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="575"/>
        <source>the file has version %1, newer than this build of Gyre reads (%2 and older); open it with a newer Gyre</source>
        <translation>文件版本为 %1，比此 Gyre 版本可读取的版本（%2 及更早）更新；请用更新的 Gyre 打开</translation>
    </message>
    <message>
        <location filename="../src/model/output_target.cpp" line="42"/>
        <location filename="../src/model/project_file.cpp" line="740"/>
        <source>is a directory, not a file</source>
        <translation>是目录，不是文件</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="743"/>
        <source>cannot open: %1</source>
        <translation>无法打开：%1</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="647"/>
        <source>cannot read: %1</source>
        <translation>无法读取：%1</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="660"/>
        <source>is empty; a project file holds a JSON object</source>
        <translation>为空；项目文件应包含一个 JSON 对象</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="653"/>
        <source>not valid JSON: %1 at byte %2</source>
        <translation>不是有效的 JSON：%1（位于第 %2 字节）</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="758"/>
        <source>not saved, because the file would not read back: %1</source>
        <translation>未保存，因为该文件无法被重新读取：%1</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="79"/>
        <source>object %1 &apos;%2&apos; is written as &apos;%3&apos; so that its name is unique</source>
        <translation>对象 %1“%2”写为“%3”，以使其名称唯一</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="481"/>
        <source>cannot be written as FBX: %1</source>
        <translation>无法写成 FBX：%1</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="195"/>
        <source>baking at %1 fps gives more than %2 samples</source>
        <translation>以 %1 fps 烘焙会产生超过 %2 个采样</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="202"/>
        <source>the motion of &apos;%1&apos; cannot be baked: %2</source>
        <translation>无法烘焙“%1”的运动：%2</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="174"/>
        <source>the motion of &apos;%1&apos; cannot be evaluated: %2</source>
        <translation>无法计算“%1”的运动：%2</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="141"/>
        <source>object %1 names parent %2, which does not come before it; it is written at the top level</source>
        <translation>对象 %1 指定的父对象 %2 不在它之前；它被写在顶层</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="157"/>
        <source>the skin of &apos;%1&apos; names object %2, which the scene does not hold; its mesh is written rigid</source>
        <translation>&apos;%1&apos; 的蒙皮引用了场景中不存在的物体 %2；其网格按刚体写出</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="184"/>
        <source>the mesh of &apos;%1&apos; has an index past its vertices</source>
        <translation>“%1”的网格有超出其顶点范围的索引</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="411"/>
        <source>Assimp cannot write it</source>
        <translation>Assimp 无法写入</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="412"/>
        <source>Assimp cannot write it: %1</source>
        <translation>Assimp 无法写入：%1</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="418"/>
        <source>Assimp wrote nothing</source>
        <translation>Assimp 没有写出任何内容</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="437"/>
        <source>cannot be written as glTF: %1</source>
        <translation>无法写成 glTF：%1</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="461"/>
        <source>the frame rate must be a finite number above zero</source>
        <translation>帧率必须是大于零的有限数</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="463"/>
        <source>the scene&apos;s time range is empty or not finite</source>
        <translation>场景的时间范围为空或不是有限值</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="466"/>
        <source>the scene has no meshes, and OBJ holds nothing else</source>
        <translation>场景没有网格，而 OBJ 不能保存其他内容</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="468"/>
        <source>OBJ holds no motion: the meshes are written as posed at the start time</source>
        <translation>OBJ 不包含运动：网格按起始时间的姿态写出</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="58"/>
        <source>no such file</source>
        <translation>文件不存在</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="60"/>
        <source>is a directory, not a scene file</source>
        <translation>是目录，不是场景文件</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="62"/>
        <source>cannot be read (permission denied)</source>
        <translation>无法读取（权限不足）</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="64"/>
        <source>the file is empty</source>
        <translation>文件为空</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="77"/>
        <source>the file holds no meshes and no animation</source>
        <translation>文件既没有网格也没有动画</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="86"/>
        <source>not a scene Gyre can read: %1</source>
        <translation>不是 Gyre 能读取的场景：%1</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="90"/>
        <source>the file holds no scene nodes</source>
        <translation>文件不含场景节点</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="132"/>
        <source>%1 key %2 is not finite</source>
        <translation>%1关键帧 %2 不是有限值</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="135"/>
        <source>%1 key %2 is not a rotation (a zero quaternion)</source>
        <translation>%1关键帧 %2 不是旋转（零四元数）</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="138"/>
        <source>%1 key %2 is not after the key before it</source>
        <translation>%1关键帧 %2 不在前一个关键帧之后</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="147"/>
        <source>node &apos;%1&apos;: %2</source>
        <translation>节点“%1”：%2</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="395"/>
        <source>node &apos;%1&apos; has more than one channel in animation &apos;%2&apos;; the first is used</source>
        <translation>节点“%1”在动画“%2”中有多个通道；使用第一个</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="401"/>
        <source>node &apos;%1&apos; is moved by more than one of the chosen animations; the later one, &apos;%2&apos;, is used</source>
        <translation>节点“%1”被多个所选动画移动；使用较后的“%2”</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="505"/>
        <source>animation &apos;%1&apos; moves &apos;%2&apos;, which is not in the scene</source>
        <translation>动画“%1”移动“%2”，但场景中没有它</translation>
    </message>
    <message numerus="yes">
        <location filename="../src/io/scene_import.cpp" line="536"/>
        <source>the file has %n animation(s); there is no animation %1</source>
        <translation>
            <numerusform>文件有 %n 个动画；没有动画 %1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="560"/>
        <source>the frame rate %1 is not in (0, %2]</source>
        <translation>帧率 %1 不在 (0, %2] 范围内</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="567"/>
        <source>the unit %1 m is not a positive length</source>
        <translation>单位 %1 m 不是正的长度</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="671"/>
        <source>Assimp reads %1 animations and TinyGLTF %2</source>
        <translation>Assimp 读到 %1 个动画，而 TinyGLTF 读到 %2 个</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="451"/>
        <source>node &apos;%1&apos; has a non-uniform scale; its children get the mean scale</source>
        <translation>节点“%1”的缩放不均匀；其子节点使用平均缩放</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="258"/>
        <source>mesh &apos;%1&apos;: %2</source>
        <translation>网格“%1”：%2</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="469"/>
        <source>rotation</source>
        <translation>旋转</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="472"/>
        <source>position</source>
        <translation>位置</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="487"/>
        <source>scaling</source>
        <translation>缩放</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="493"/>
        <source>node &apos;%1&apos;: its scale changes over time; Gyre&apos;s motion is rigid, so the scale of its first key is kept</source>
        <translation>节点“%1”：其缩放随时间变化；Gyre 的运动是刚体运动，因此保留其第一个关键帧的缩放</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="549"/>
        <source>mesh and morph animation is not imported; only node motion is</source>
        <translation>网格动画和变形动画不会被导入；只导入节点运动</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="551"/>
        <source>cameras and lights are not imported</source>
        <translation>摄像机和灯光不会被导入</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="24"/>
        <source>a boolean</source>
        <translation>布尔值</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="26"/>
        <location filename="../src/model/json_field.cpp" line="48"/>
        <source>a number</source>
        <translation>数字</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="29"/>
        <source>the string &quot;%1&quot;</source>
        <translation>字符串“%1”</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="33"/>
        <location filename="../src/model/json_field.cpp" line="52"/>
        <source>an array</source>
        <translation>数组</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="35"/>
        <location filename="../src/model/json_field.cpp" line="54"/>
        <source>an object</source>
        <translation>对象</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="39"/>
        <source>nothing</source>
        <translation>无</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="46"/>
        <source>true or false</source>
        <translation>true 或 false</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="50"/>
        <source>a string</source>
        <translation>字符串</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="70"/>
        <source>the top level</source>
        <translation>顶层</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="77"/>
        <source>expected %1, found %2</source>
        <translation>应为%1，实际为%2</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="88"/>
        <source>missing</source>
        <translation>缺失</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="116"/>
        <location filename="../src/model/value_checks.cpp" line="66"/>
        <source>%1 is not a finite number</source>
        <translation>%1 不是有限数</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="124"/>
        <source>%1 is not a whole number</source>
        <translation>%1 不是整数</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="126"/>
        <source>%1 is outside %2 to %3</source>
        <translation>%1 超出 %2 到 %3 的范围</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="146"/>
        <source>not valid base64</source>
        <translation>不是有效的 Base64</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="155"/>
        <source>expected %1 numbers, found %2</source>
        <translation>应为 %1 个数字，实际为 %2 个</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="30"/>
        <source>not all components are finite</source>
        <translation>并非所有分量都是有限值</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="40"/>
        <source>the %1 is zero</source>
        <translation>%1为零</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="42"/>
        <source>the %1 has length %2; it must have length 1</source>
        <translation>%1的长度为 %2；长度必须为 1</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="73"/>
        <source>%1 is negative</source>
        <translation>%1 为负数</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="80"/>
        <source>%1 is not positive</source>
        <translation>%1 不是正数</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="86"/>
        <source>direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="90"/>
        <source>quaternion</source>
        <translation>四元数</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="101"/>
        <source>position coordinate %1 is beyond ±%2</source>
        <translation>位置坐标 %1 超出 ±%2</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="109"/>
        <source>time %1 is beyond ±%2 s</source>
        <translation>时间 %1 超出 ±%2 秒</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="116"/>
        <source>time %1 does not come after the time before it, %2</source>
        <translation>时间 %1 不在前一个时间 %2 之后</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="125"/>
        <source>the value has length %1; a fitted value needs length at least %2</source>
        <translation>该值的长度为 %1；拟合值的长度至少须为 %2</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="134"/>
        <source>the derivative has length %1 per second; the most it may have is %2</source>
        <translation>导数的长度为每秒 %1；最大允许为 %2</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="160"/>
        <source>a stroke has no times or one per point</source>
        <translation>笔画要么没有时间，要么每个点有一个时间</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="176"/>
        <source>the pattern&apos;s repeat count %1 is negative</source>
        <translation>图案的重复次数 %1 为负数</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="213"/>
        <source>subdivision levels %1 are outside 0 to %2</source>
        <translation>细分层级 %1 超出 0 到 %2 的范围</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="219"/>
        <source>%1 keys on a ballistic track, which solves a free flight for each span; it may hold %2</source>
        <translation>弹道轨迹上有 %1 个关键帧，它为每个区间求解一次自由飞行；最多可容纳 %2 个</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="227"/>
        <source>%1 keys at %2 levels make %3 poses; the budget is %4</source>
        <translation>%1 个关键帧经 %2 层细分得到 %3 个姿态；上限为 %4</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="244"/>
        <source>a frame rate of %1 is above %2</source>
        <translation>帧率 %1 高于 %2</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="252"/>
        <source>the end time %1 does not come after the start time %2</source>
        <translation>结束时间 %1 不在开始时间 %2 之后</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="257"/>
        <source>%1 s at %2 fps make %3 frames; the budget is %4</source>
        <translation>%1 秒以 %2 fps 计为 %3 帧；上限为 %4</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="266"/>
        <source>a mesh position is not finite</source>
        <translation>网格的某个位置不是有限值</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="269"/>
        <source>a mesh normal is not finite</source>
        <translation>网格的某个法线不是有限值</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="271"/>
        <source>the mesh has %1 normals for %2 positions</source>
        <translation>网格有 %1 个法线，却有 %2 个位置</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="273"/>
        <source>the mesh&apos;s %1 indices do not make whole triangles</source>
        <translation>网格的 %1 个索引不能组成完整的三角形</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="276"/>
        <source>mesh index %1 is beyond its %2 positions</source>
        <translation>网格索引 %1 超出其 %2 个位置</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="285"/>
        <source>the skin has %1 joints, more than the %2 a mesh may follow</source>
        <translation>蒙皮有 %1 个关节，超过网格可跟随的 %2 个</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="288"/>
        <source>skin joint %1 is 0 or named twice</source>
        <translation>蒙皮关节 %1 为 0 或被重复指定</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="290"/>
        <source>the skin has %1 inverse bind matrices for %2 joints</source>
        <translation>蒙皮为 %2 个关节提供了 %1 个逆绑定矩阵</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="294"/>
        <source>the inverse bind matrix of skin joint %1 is not a finite affine transform</source>
        <translation>蒙皮关节 %1 的逆绑定矩阵不是有限的仿射变换</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="297"/>
        <source>the skin has %1 joint sets and %2 weight sets for %3 positions</source>
        <translation>蒙皮为 %3 个位置提供了 %1 组关节和 %2 组权重</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="304"/>
        <source>skin vertex %1 names joint %2 of %3</source>
        <translation>蒙皮顶点 %1 指向 %3 个关节中的第 %2 个</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="307"/>
        <source>the weights of skin vertex %1 are not finite, ≥ 0 and at most 1 in sum</source>
        <translation>蒙皮顶点 %1 的权重不是有限、≥ 0 且总和至多为 1 的数</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="28"/>
        <source>%1 GiB</source>
        <translation>%1 GiB</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="29"/>
        <source>%1 MiB</source>
        <translation>%1 MiB</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="154"/>
        <source>the scene reader %1 is not installed beside %2</source>
        <translation>场景读取程序 %1 未安装在 %2 中</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="158"/>
        <source>the scene reader %1 is missing or not executable</source>
        <translation>场景读取程序 %1 不存在或不可执行</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="174"/>
        <source>the scene reader %1 cannot be started: %2</source>
        <translation>无法启动场景读取程序 %1：%2</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="119"/>
        <source>the scene reader took longer than %1 s and was stopped; the file may be damaged or too large</source>
        <translation>场景读取程序运行超过 %1 秒，已被停止；文件可能已损坏或过大</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="123"/>
        <source>the scene reader&apos;s reply is larger than %1</source>
        <translation>场景读取程序的回复大于 %1</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="133"/>
        <source>the scene reader crashed on this file (signal %1, %2)%3</source>
        <translation>场景读取程序读取此文件时崩溃（信号 %1，%2）%3</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="191"/>
        <source>the scene reader needed more than %1 of memory for this file and was stopped</source>
        <translation>场景读取程序读取此文件需要超过 %1 的内存，已被停止</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="137"/>
        <source>the scene reader failed (exit status %1)%2</source>
        <translation>场景读取程序失败（退出状态 %1）%2</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="102"/>
        <source>the scene reader&apos;s reply is malformed: %1</source>
        <translation>场景读取程序的回复格式错误：%1</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="106"/>
        <source>the scene reader&apos;s reply is malformed: the wrong kind of reply</source>
        <translation>场景读取程序的回复格式错误：回复类型不对</translation>
    </message>
    <message>
        <location filename="../src/io/baked_scene.cpp" line="171"/>
        <source>glTF times cannot be negative: the motion is written %1 s later, from 0 s</source>
        <translation>glTF 的时间不能为负：运动推后 %1 秒写出，从 0 秒开始</translation>
    </message>
    <message>
        <location filename="../src/io/baked_scene.cpp" line="190"/>
        <source>&apos;%1&apos;: two of its keys are within a float32 step; its rotation and translation are written as baked samples, not as its splines</source>
        <translation>“%1”：它有两个关键帧相距不到一个 float32 步长；其旋转和平移以烘焙采样写出，而不是以其样条写出</translation>
    </message>
    <message>
        <location filename="../src/io/baked_scene.cpp" line="197"/>
        <source>&apos;%1&apos;: %2 baked samples are left out, each within a float32 step of the one kept (glTF stores times as float32)</source>
        <translation>“%1”：省略了 %2 个烘焙采样，每个都与保留的采样相距不到一个 float32 步长（glTF 以 float32 存储时间）</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="29"/>
        <source>%1 is %2 bytes, over the %3 bytes a glTF buffer may have</source>
        <translation>%1 有 %2 字节，超过 glTF 缓冲区允许的 %3 字节</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="63"/>
        <source>there is no accessor %1</source>
        <translation>不存在访问器（accessor）%1</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="67"/>
        <source>count %1 is over the %2 elements Gyre reads</source>
        <translation>数量 %1 超过 Gyre 读取的 %2 个元素</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="75"/>
        <source>there is no buffer view %1</source>
        <translation>不存在缓冲区视图（buffer view）%1</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="78"/>
        <source>its buffer view names no buffer</source>
        <translation>其缓冲区视图未指定缓冲区</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="84"/>
        <source>%1 elements from byte %2 run past its buffer view&apos;s %3 bytes</source>
        <translation>从第 %2 字节起的 %1 个元素超出其缓冲区视图的 %3 字节</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="89"/>
        <source>its buffer view runs past the buffer&apos;s %1 bytes</source>
        <translation>其缓冲区视图超出缓冲区的 %1 字节</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="102"/>
        <source>there is no such sampler</source>
        <translation>不存在该采样器</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="113"/>
        <source>&apos;%1&apos; is not an interpolation</source>
        <translation>“%1”不是插值方式</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="122"/>
        <source>%1 times need %2 output elements; the output has %3</source>
        <translation>%1 个时间需要 %2 个输出元素；输出只有 %3 个</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="130"/>
        <source>time %1 is not finite or not after the one before it</source>
        <translation>时间 %1 不是有限值，或不在前一个时间之后</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="138"/>
        <source>element %1 is not finite</source>
        <translation>元素 %1 不是有限值</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="149"/>
        <source>rotation %1 is a zero quaternion</source>
        <translation>旋转 %1 是零四元数</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="220"/>
        <source>not a glTF file Gyre can read: %1</source>
        <translation>不是 Gyre 能读取的 glTF 文件：%1</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="337"/>
        <source>node &apos;%1&apos;: its motion at %2 fps needs more than %3 keys</source>
        <translation>节点“%1”：其运动在 %2 fps 下需要超过 %3 个关键帧</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="164"/>
        <source>the FBX time mode</source>
        <translation>FBX 的时间模式</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="171"/>
        <source>the BVH frame time</source>
        <translation>BVH 的帧时间（Frame Time）</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="176"/>
        <source>every key is on a frame of %1 fps</source>
        <translation>每个关键帧都落在 %1 fps 的帧上</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="180"/>
        <source>no animation; Gyre&apos;s default</source>
        <translation>没有动画；Gyre 的默认值</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="181"/>
        <source>the keys are on the frames of no common rate; Gyre&apos;s default</source>
        <translation>关键帧不在任何共同帧率的帧上；Gyre 的默认值</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="188"/>
        <source>written by Assimp, whose FBX unit says nothing; metres assumed</source>
        <translation>由 Assimp 写出，其 FBX 单位不可作准；假定为米</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="195"/>
        <source>the FBX UnitScaleFactor, %1 cm</source>
        <translation>FBX 的 UnitScaleFactor，%1 cm</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="198"/>
        <source>FBX&apos;s default, 1 cm</source>
        <translation>FBX 的默认值，1 cm</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="205"/>
        <source>the Collada &lt;unit&gt;</source>
        <translation>Collada 的 &lt;unit&gt;</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="208"/>
        <source>Collada&apos;s default, 1 m</source>
        <translation>Collada 的默认值，1 m</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="211"/>
        <source>glTF is in metres</source>
        <translation>glTF 以米为单位</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="212"/>
        <source>the format has no unit; metres assumed</source>
        <translation>该格式没有单位；假定为米</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="229"/>
        <source>the file says its up axis is %1; Gyre converts Y-up and Z-up scenes only, so it is read as Y-up</source>
        <translation>文件声明其向上轴为 %1；Gyre 只转换 Y 朝上和 Z 朝上的场景，因此按 Y 朝上读取</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="237"/>
        <source>the FBX UpAxis</source>
        <translation>FBX 的 UpAxis</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="246"/>
        <source>the Collada &lt;up_axis&gt;</source>
        <translation>Collada 的 &lt;up_axis&gt;</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="250"/>
        <source>Collada&apos;s default, Y</source>
        <translation>Collada 的默认值，Y</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="255"/>
        <source>glTF is Y-up</source>
        <translation>glTF 为 Y 朝上</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="255"/>
        <source>Y-up assumed</source>
        <translation>假定 Y 朝上</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_takes.cpp" line="90"/>
        <source>&apos;%1&apos; plays take %2 &apos;%3&apos;</source>
        <translation>“%1”播放 take %2“%3”</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_takes.cpp" line="92"/>
        <source>the file&apos;s %1 takes are Blender&apos;s, one for every object and action; each object gets its own action: %2</source>
        <translation>文件的 %1 个 take 来自 Blender，每个对象与动作的组合各一个；每个对象各取自己的动作：%2</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_skin.cpp" line="42"/>
        <source>mesh &apos;%1&apos;, bone &apos;%2&apos;: %3</source>
        <translation>网格“%1”，骨骼“%2”：%3</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_skin.cpp" line="47"/>
        <source>its offset matrix is not finite</source>
        <translation>其偏移矩阵不是有限值</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_skin.cpp" line="51"/>
        <source>weight %1 names vertex %2 of %3</source>
        <translation>权重 %1 指向 %3 个顶点中的第 %2 个</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_skin.cpp" line="53"/>
        <source>weight %1 is not a finite number ≥ 0</source>
        <translation>权重 %1 不是 ≥ 0 的有限数</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_skin.cpp" line="63"/>
        <source>mesh &apos;%1&apos; has %2 bones, more than the %3 Gyre can skin; it shows in its bind pose</source>
        <translation>网格“%1”有 %2 根骨骼，超过 Gyre 可蒙皮的 %3 根；它以绑定姿势显示</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_skin.cpp" line="74"/>
        <source>mesh &apos;%1&apos;: its bone &apos;%2&apos; is not a node of the scene; it shows in its bind pose</source>
        <translation>网格“%1”：其骨骼“%2”不是场景中的节点；它以绑定姿势显示</translation>
    </message>
    <message>
        <location filename="../src/model/key_clipboard.cpp" line="40"/>
        <source>the text is not keys copied from Gyre</source>
        <translation>该文本不是从 Gyre 复制的关键帧</translation>
    </message>
    <message>
        <location filename="../src/model/key_clipboard.cpp" line="42"/>
        <source>%1 bytes of text are more than the %2 that keys may take</source>
        <translation>%1 字节的文本超过了关键帧允许的 %2 字节</translation>
    </message>
    <message>
        <location filename="../src/model/key_clipboard.cpp" line="69"/>
        <source>no keys were copied</source>
        <translation>没有复制任何关键帧</translation>
    </message>
    <message>
        <location filename="../src/model/key_clipboard.cpp" line="71"/>
        <source>%1 keys are more than the %2 a project may hold</source>
        <translation>%1 个关键帧超过了项目可容纳的 %2 个</translation>
    </message>
    <message>
        <location filename="../src/model/key_clipboard.cpp" line="73"/>
        <source>a pose is one object&apos;s one key</source>
        <translation>姿势是一个物体的一个关键帧</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="52"/>
        <source>the inertia has a value that is not a finite number</source>
        <translation>惯性张量含有非有限数值</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="54"/>
        <source>the inertia tensor is not symmetric</source>
        <translation>惯性张量不对称</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="56"/>
        <source>the inertia tensor is not positive definite: every principal moment must be above 0</source>
        <translation>惯性张量不是正定的：每个主惯性矩都必须大于 0</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="58"/>
        <source>no body has this inertia: its two smaller principal moments add up to less than the largest</source>
        <translation>没有物体具有这样的惯性：两个较小的主惯性矩之和小于最大的</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="80"/>
        <source>as typed</source>
        <translation>按输入值</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="82"/>
        <source>from the mesh, solid</source>
        <translation>来自网格，实心</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="84"/>
        <source>from the mesh, as a thin shell: the mesh is not closed</source>
        <translation>来自网格，作为薄壳：网格不封闭</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="86"/>
        <source>from the mesh&apos;s bounding box: the mesh has no area</source>
        <translation>来自网格的包围盒：网格没有面积</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="94"/>
        <source>the mass must be a number above 0</source>
        <translation>质量必须是大于 0 的数</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="96"/>
        <source>the centre of mass is not a finite point</source>
        <translation>质心不是有限点</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="116"/>
        <source>the inertia needs six numbers: Ixx, Iyy, Izz, Ixy, Ixz, Iyz</source>
        <translation>惯性张量需要六个数：Ixx、Iyy、Izz、Ixy、Ixz、Iyz</translation>
    </message>
    <message>
        <location filename="../src/model/flight_choices.cpp" line="25"/>
        <source>%1 flight choices for %2 spans between the keys: one a span at most</source>
        <translation>关键帧之间有 %2 个区间，却有 %1 个飞行选择：每个区间最多一个</translation>
    </message>
    <message>
        <location filename="../src/model/project_json.cpp" line="74"/>
        <source>&apos;%1&apos; is neither quaternion nor euler</source>
        <translation>&apos;%1&apos; 既不是 quaternion 也不是 euler</translation>
    </message>
    <message>
        <location filename="../src/model/project_json.cpp" line="79"/>
        <source>&apos;%1&apos; is neither intrinsic nor extrinsic</source>
        <translation>&apos;%1&apos; 既不是 intrinsic 也不是 extrinsic</translation>
    </message>
    <message>
        <location filename="../src/model/project_json.cpp" line="84"/>
        <source>&apos;%1&apos; is not an order of three axes</source>
        <translation>&apos;%1&apos; 不是三个轴的顺序</translation>
    </message>
</context>
<context>
    <name>gyre::app::AddObjectActions</name>
    <message>
        <location filename="../src/app/add_object_actions.cpp" line="41"/>
        <location filename="../src/app/add_object_actions.cpp" line="57"/>
        <source>Empty</source>
        <translation>空物体</translation>
    </message>
    <message>
        <location filename="../src/app/add_object_actions.cpp" line="65"/>
        <source>Add %1</source>
        <translation>添加%1</translation>
    </message>
</context>
<context>
    <name>gyre::app::ChannelListModel</name>
    <message>
        <location filename="../src/app/graph_editor/channel_list_model.cpp" line="60"/>
        <source>Euler %1 (°)</source>
        <translation>欧拉角 %1 (°)</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/channel_list_model.cpp" line="62"/>
        <source>quaternion w</source>
        <translation>四元数 w</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/channel_list_model.cpp" line="66"/>
        <source>quaternion %1</source>
        <translation>四元数 %1</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/channel_list_model.cpp" line="70"/>
        <source>ω %1 (rad/s)</source>
        <translation>ω %1 (rad/s)</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/channel_list_model.cpp" line="72"/>
        <source>|ω| (rad/s)</source>
        <translation>|ω| (rad/s)</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/channel_list_model.cpp" line="76"/>
        <source>position %1</source>
        <translation>位置 %1</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/channel_list_model.cpp" line="80"/>
        <source>L %1 (kg·m²/s)</source>
        <translation>L %1 (kg·m²/s)</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/channel_list_model.cpp" line="82"/>
        <source>|L| (kg·m²/s)</source>
        <translation>|L| (kg·m²/s)</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/channel_list_model.cpp" line="84"/>
        <source>rotational energy (J)</source>
        <translation>转动能 (J)</translation>
    </message>
</context>
<context>
    <name>gyre::app::DrawnMotion</name>
    <message>
        <location filename="../src/app/viewport/drawn_motion.cpp" line="16"/>
        <source>The motion could not be rebuilt: %1</source>
        <translation>无法重建运动：%1</translation>
    </message>
    <message>
        <location filename="../src/app/viewport/drawn_motion.cpp" line="26"/>
        <location filename="../src/app/viewport/drawn_motion.cpp" line="43"/>
        <source>The trail could not be built: %1</source>
        <translation>无法生成频闪轨迹：%1</translation>
    </message>
</context>
<context>
    <name>gyre::app::FitController</name>
    <message>
        <location filename="../src/app/sketch/fit_controller.cpp" line="21"/>
        <source>Against what was drawn: %1 rad²/s before, %2 after.</source>
        <translation>与所绘草图相比：拟合前 %1 rad²/s，拟合后 %2。</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_controller.cpp" line="27"/>
        <source>Fit applied: the motion now follows the sketch within δ = %1 (largest relative error %2, %3 rounds, %4 s).</source>
        <translation>已应用拟合：运动现在在 δ = %1 以内贴合草图（最大相对误差 %2，%3 轮，%4 秒）。</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_controller.cpp" line="34"/>
        <source>Fit stopped at its limit of added control points, still off the sketch by a relative error of up to %1 (δ = %2); its last result was applied.</source>
        <translation>拟合已达到新增控制点的上限而停止，与草图仍有最多 %1 的相对误差（δ = %2）；已应用其最后结果。</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_controller.cpp" line="39"/>
        <source>Fit could not meet δ = %1: where it is furthest off (relative error %2) it has no room for another control point, often because constrained keys there disagree with the sketch; its result was applied.</source>
        <translation>拟合未能达到 δ = %1：在偏差最大处（相对误差 %2）已无空间再加入控制点，通常是因为该处的约束关键帧与草图不一致；已应用其结果。</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_controller.cpp" line="48"/>
        <source>Fit stopped after %1 rounds, still off the sketch by a relative error of up to %2 (δ = %3); its last result was applied.</source>
        <translation>拟合在 %1 轮后停止，与草图仍有最多 %2 的相对误差（δ = %3）；已应用其最后结果。</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_controller.cpp" line="67"/>
        <source>Fit failed, nothing was applied: %1</source>
        <translation>拟合失败，未应用任何内容：%1</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_controller.cpp" line="69"/>
        <source>Fit cancelled; nothing was applied.</source>
        <translation>已取消拟合；未应用任何内容。</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_controller.cpp" line="139"/>
        <source>Fit not applied: the track changed while it ran.</source>
        <translation>未应用拟合：拟合运行期间轨道已更改。</translation>
    </message>
</context>
<context>
    <name>gyre::app::FitPanel</name>
    <message>
        <location filename="../src/app/sketch/fit_panel.cpp" line="71"/>
        <source>Fitting…</source>
        <translation>正在拟合…</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_panel.cpp" line="276"/>
        <source>Not changed: %1.</source>
        <translation>未更改：%1。</translation>
    </message>
</context>
<context>
    <name>gyre::app::FitProgress</name>
    <message>
        <location filename="../src/app/sketch/fit_progress.cpp" line="20"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_progress.cpp" line="26"/>
        <source>Stop the fit; the motion stays as it is</source>
        <translation>停止拟合；运动保持不变</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_progress.cpp" line="43"/>
        <source>Fitting…</source>
        <translation>正在拟合…</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_progress.cpp" line="53"/>
        <source>Fit: round %v of %m, largest relative error %1</source>
        <translation>拟合：第 %v 轮，共 %m 轮，最大相对误差 %1</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_progress.cpp" line="54"/>
        <source>Fit: round %v of %m</source>
        <translation>拟合：第 %v 轮，共 %m 轮</translation>
    </message>
</context>
<context>
    <name>gyre::app::GraphEditorPanel</name>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="103"/>
        <source>The channels to plot: check one to show its curve</source>
        <translation>要绘制的通道：勾选一个以显示其曲线</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="145"/>
        <source>The order of the Euler angles, as the inspector shows them</source>
        <translation>欧拉角的顺序，与检查器中显示的相同</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="146"/>
        <source>Euler &amp;order:</source>
        <translation>欧拉顺序(&amp;O)：</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="150"/>
        <source>world frame</source>
        <translation>世界坐标系</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="151"/>
        <source>object&apos;s frame</source>
        <translation>对象坐标系</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="152"/>
        <source>The frame the angular velocity&apos;s and angular momentum&apos;s components are given in</source>
        <translation>角速度和角动量分量所用的坐标系</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="153"/>
        <source>ω &amp;in:</source>
        <translation>ω 坐标系(&amp;I)：</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="158"/>
        <source>Frame &amp;All</source>
        <translation>显示全部(&amp;A)</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="159"/>
        <source>Show the whole time range and every shown curve (Home)</source>
        <translation>显示整个时间范围和所有显示的曲线 (Home)</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="160"/>
        <source>Frame &amp;Selected</source>
        <translation>显示所选(&amp;S)</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="162"/>
        <source>Show the selected key between its neighbours</source>
        <translation>在相邻关键帧之间显示所选关键帧</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="170"/>
        <source>&amp;Move Keys</source>
        <translation>移动关键帧(&amp;M)</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="172"/>
        <source>Move the selected keys with the pointer; click to keep, Esc to cancel</source>
        <translation>用指针移动所选关键帧；单击保留，Esc 取消</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="173"/>
        <source>&amp;Scale Keys</source>
        <translation>缩放关键帧(&amp;S)</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="175"/>
        <source>Scale the selected keys&apos; times about the current frame; click to keep, Esc to cancel</source>
        <translation>以当前帧为中心缩放所选关键帧的时间；单击保留，Esc 取消</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="225"/>
        <source>time (s)</source>
        <translation>时间 (s)</translation>
    </message>
</context>
<context>
    <name>gyre::app::ImportDialog</name>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="29"/>
        <source>The file has no animation.</source>
        <translation>文件没有动画。</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="31"/>
        <source>The file has one animation.</source>
        <translation>文件有一个动画。</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="33"/>
        <source>Each animation moves nodes no other moves, so all are imported together.</source>
        <translation>每个动画移动的节点都不被其他动画移动，因此全部一起导入。</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="35"/>
        <source>These are Blender&apos;s takes, one for every object and action: each object gets its own action.</source>
        <translation>这些是 Blender 的 take，每个对象与动作的组合各一个：每个对象各取自己的动作。</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="38"/>
        <source>These animations move the same nodes: choose which to import. Checked ones are merged; a node that several move takes the keys of the last one in the list.</source>
        <translation>这些动画移动相同的节点：请选择要导入哪些。勾选的动画会被合并；被多个动画移动的节点采用列表中最后一个动画的关键帧。</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="46"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="66"/>
        <source>Euler filter: rotations in Euler mode (extrinsic xyz), angles continuous</source>
        <translation>欧拉滤波器：旋转采用欧拉模式（外旋 xyz），角度连续</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="70"/>
        <source>Import %1</source>
        <translation>导入 %1</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="76"/>
        <source>Animation</source>
        <translation>动画</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="76"/>
        <source>Length</source>
        <translation>时长</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="76"/>
        <source>Moves</source>
        <translation>移动的节点</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="79"/>
        <source>(unnamed %1)</source>
        <translation>（未命名 %1）</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="104"/>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="107"/>
        <source>Frame rate:</source>
        <translation>帧率：</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="111"/>
        <source> m</source>
        <translation> 米</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="114"/>
        <source>One unit of the file:</source>
        <translation>文件中的一个单位：</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="116"/>
        <source>Y up (turned to Z up)</source>
        <translation>Y 朝上（转为 Z 朝上）</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="117"/>
        <source>Z up</source>
        <translation>Z 朝上</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="120"/>
        <source>Up axis:</source>
        <translation>向上轴：</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="122"/>
        <source>First key at 0 s</source>
        <translation>第一个关键帧位于 0 秒</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="123"/>
        <source>As in the file</source>
        <translation>与文件中相同</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="124"/>
        <source>Time:</source>
        <translation>时间：</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="127"/>
        <source>Stores each imported rotation as Euler angles, Blender&apos;s default XYZ order, each key&apos;s angles the nearest to the key before, so that a spin is a ramp, not a saw-tooth</source>
        <translation>将每个导入的旋转存储为欧拉角（Blender 默认的 XYZ 顺序），每个关键帧的角度取最接近前一关键帧的值，使旋转呈斜坡而非锯齿</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="129"/>
        <source>Rotations:</source>
        <translation>旋转：</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="131"/>
        <source>From the file: %1; %2; %3.</source>
        <translation>来自文件：%1；%2；%3。</translation>
    </message>
</context>
<context>
    <name>gyre::app::InspectorWidget</name>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="79"/>
        <source>time</source>
        <translation>时间</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="81"/>
        <source>position x</source>
        <translation>位置 x</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="81"/>
        <source>position y</source>
        <translation>位置 y</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="81"/>
        <source>position z</source>
        <translation>位置 z</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="84"/>
        <source>quaternion w</source>
        <translation>四元数 w</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="84"/>
        <source>quaternion x</source>
        <translation>四元数 x</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="84"/>
        <source>quaternion y</source>
        <translation>四元数 y</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="84"/>
        <source>quaternion z</source>
        <translation>四元数 z</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="91"/>
        <source>matrix row %1, column %2</source>
        <translation>矩阵第 %1 行第 %2 列</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="94"/>
        <source>axis x</source>
        <translation>轴 x</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="94"/>
        <source>axis y</source>
        <translation>轴 y</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="94"/>
        <source>axis z</source>
        <translation>轴 z</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="94"/>
        <source>angle</source>
        <translation>角度</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="96"/>
        <source>first angle</source>
        <translation>第一个角</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="96"/>
        <source>second angle</source>
        <translation>第二个角</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="96"/>
        <source>third angle</source>
        <translation>第三个角</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="132"/>
        <source>Quaternions</source>
        <translation>四元数</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="133"/>
        <source>Euler angles</source>
        <translation>欧拉角</translation>
    </message>
    <message>
        <location filename="../src/app/euler_convention_choosers.cpp" line="29"/>
        <source>extrinsic (fixed axes)</source>
        <translation>外旋（固定轴）</translation>
    </message>
    <message>
        <location filename="../src/app/euler_convention_choosers.cpp" line="31"/>
        <source>intrinsic (moving axes)</source>
        <translation>内旋（随动轴）</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="158"/>
        <source>about %1 (°)</source>
        <translation>绕 %1（°）</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="183"/>
        <source>The rotation mode was not changed: %1.</source>
        <translation>旋转模式未更改：%1。</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="207"/>
        <source>%1, keyframe %2 of %3</source>
        <translation>%1，第 %2 个关键帧，共 %3 个</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="244"/>
        <source>Near gimbal lock (%1° from it): the first and third angles turn about almost the same axis, so only their sum (or difference) is determined. Small changes of the rotation can swing them widely.</source>
        <translation>接近万向节锁（相差 %1°）：第一个角和第三个角几乎绕同一根轴旋转，因此只有它们的和（或差）是确定的。旋转的微小变化可能使它们大幅摆动。</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="286"/>
        <source>The keyframe was not moved: %1.</source>
        <translation>关键帧未移动：%1。</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="297"/>
        <source>The constraint was not changed: %1.</source>
        <translation>约束未更改：%1。</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="305"/>
        <source>The position was not changed: %1.</source>
        <translation>位置未更改：%1。</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="317"/>
        <location filename="../src/app/inspector_widget.cpp" line="340"/>
        <location filename="../src/app/inspector_widget.cpp" line="366"/>
        <location filename="../src/app/inspector_widget.cpp" line="389"/>
        <source>The rotation was not changed: %1.</source>
        <translation>旋转未更改：%1。</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="322"/>
        <source>The rotation was not changed: the zero quaternion is no rotation.</source>
        <translation>旋转未更改：零四元数不表示旋转。</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="330"/>
        <source>The quaternion had length %1; it was scaled to length 1.</source>
        <translation>四元数的长度为 %1；已缩放为长度 1。</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="347"/>
        <source>The rotation was not changed: the matrix has determinant %1, so it flattens or mirrors space and is not a rotation.</source>
        <translation>旋转未更改：矩阵的行列式为 %1，它会压扁或镜像空间，不是旋转。</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="355"/>
        <source>The matrix was not a rotation (its rows were up to %1 from orthonormal); the nearest rotation was used.</source>
        <translation>该矩阵不是旋转（其各行与正交归一最多相差 %1）；已改用最接近的旋转。</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="372"/>
        <source>The rotation was not changed: a zero axis names no direction to turn about.</source>
        <translation>旋转未更改：零轴没有给出旋转方向。</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="377"/>
        <source>The axis had length %1; it was scaled to length 1.</source>
        <translation>轴的长度为 %1；已缩放为长度 1。</translation>
    </message>
</context>
<context>
    <name>gyre::app::KeyClipboardActions</name>
    <message>
        <location filename="../src/app/key_clipboard_actions.cpp" line="55"/>
        <source>Cannot copy the pose: %1</source>
        <translation>无法复制姿势：%1</translation>
    </message>
    <message>
        <location filename="../src/app/key_clipboard_actions.cpp" line="93"/>
        <location filename="../src/app/key_clipboard_actions.cpp" line="134"/>
        <source>Cannot paste: %1</source>
        <translation>无法粘贴：%1</translation>
    </message>
    <message>
        <location filename="../src/app/key_clipboard_actions.cpp" line="114"/>
        <source>Cannot paste: no selected object has the name of a copied one</source>
        <translation>无法粘贴：没有所选物体与复制的物体同名</translation>
    </message>
    <message>
        <location filename="../src/app/key_clipboard_actions.cpp" line="115"/>
        <source>Cannot paste: no object is selected</source>
        <translation>无法粘贴：未选择物体</translation>
    </message>
</context>
<context>
    <name>gyre::app::KeyframeActions</name>
    <message>
        <location filename="../src/app/keyframe_actions.cpp" line="77"/>
        <source>Cannot add a keyframe: %1</source>
        <translation>无法添加关键帧：%1</translation>
    </message>
    <message>
        <location filename="../src/app/keyframe_actions.cpp" line="133"/>
        <source>Apply Euler Filter</source>
        <translation>应用欧拉滤波器</translation>
    </message>
    <message>
        <location filename="../src/app/keyframe_actions.cpp" line="149"/>
        <source>This span has a single free flight</source>
        <translation>此区间只有一个自由飞行</translation>
    </message>
    <message>
        <location filename="../src/app/keyframe_actions.cpp" line="151"/>
        <source>Cannot step the flight: %1</source>
        <translation>无法切换飞行：%1</translation>
    </message>
</context>
<context>
    <name>gyre::app::MagnitudePlot</name>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="151"/>
        <source>Select an object to see and sketch the speed of its rotation.</source>
        <translation>选择一个对象以查看并绘制其旋转速度的草图。</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="225"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="230"/>
        <source>Draw</source>
        <translation>绘制</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="231"/>
        <source>Left-drag draws the magnitude |ω| over time; going back erases</source>
        <translation>按住左键拖动可绘制 |ω| 随时间的大小；往回拖动则擦除</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="232"/>
        <source>Pan</source>
        <translation>平移</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="232"/>
        <source>Left-drag pans the view</source>
        <translation>按住左键拖动可平移视图</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="241"/>
        <source>Fit View</source>
        <translation>适应视图</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="242"/>
        <source>Show the scene&apos;s time range and the curves&apos; height; double-click does too</source>
        <translation>显示场景的时间范围和曲线的高度；双击也可以</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="244"/>
        <source>Clear Magnitude</source>
        <translation>清除大小</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="245"/>
        <source>Remove the sketched magnitude curve</source>
        <translation>移除草图绘制的大小曲线</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="259"/>
        <source>time (s)</source>
        <translation>时间（秒）</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="260"/>
        <source>|ω| (rad/s)</source>
        <translation>|ω|（rad/s）</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="263"/>
        <source>|ω| (°/s)</source>
        <translation>|ω|（°/s）</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="276"/>
        <source>before fit</source>
        <translation>拟合前</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="277"/>
        <source>current</source>
        <translation>当前</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="278"/>
        <source>fitted</source>
        <translation>拟合后</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="279"/>
        <source>sketched</source>
        <translation>草图</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="280"/>
        <source>constrained keys</source>
        <translation>约束的关键帧</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="282"/>
        <source>free keys</source>
        <translation>自由的关键帧</translation>
    </message>
</context>
<context>
    <name>gyre::app::MainWindow</name>
    <message>
        <location filename="../src/app/main_window.cpp" line="72"/>
        <source>Gyre projects (*.gyre)</source>
        <translation>Gyre 项目 (*.gyre)</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="181"/>
        <source>&amp;Undo</source>
        <translation>撤销(&amp;U)</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="185"/>
        <source>&amp;Redo</source>
        <translation>重做(&amp;R)</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="209"/>
        <source>&lt;opened&gt;</source>
        <translation>&lt;已打开&gt;</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="293"/>
        <source>The 3D viewport needs OpenGL 3.3, which this display does not offer. Editing, the panels and the timeline work without it.</source>
        <translation>3D 视口需要 OpenGL 3.3，而此显示环境不支持。编辑、面板和时间轴无需它也能工作。</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="346"/>
        <source>Viewport frame rate while something moves, and the time to subdivide the trail: on the worker, and from the request to its arrival</source>
        <translation>有物体运动时视口的帧率，以及细分频闪轨迹所用的时间：在后台线程中的用时，以及从请求到送达的用时</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="356"/>
        <source>%1 fps · subdivision %2 ms (%3 ms to arrive)</source>
        <translation>%1 fps · 细分 %2 毫秒（%3 毫秒后到达）</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="400"/>
        <source>Untitled</source>
        <translation>未命名</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="402"/>
        <source>%1[*] — Gyre</source>
        <translation>%1[*] — Gyre</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="417"/>
        <source>Open Project</source>
        <translation>打开项目</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="435"/>
        <source>Cannot open the project</source>
        <translation>无法打开项目</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="458"/>
        <source>L-shaped cycle (ScrewBender)</source>
        <translation>L 形循环（ScrewBender）</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="459"/>
        <source>Spinning top (sketched angular velocity)</source>
        <translation>陀螺（草图绘制的角速度）</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="460"/>
        <source>Letter M (sketched angular velocity)</source>
        <translation>字母 M（草图绘制的角速度）</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="461"/>
        <source>Hat (sketched angular velocity)</source>
        <translation>帽子（草图绘制的角速度）</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="462"/>
        <source>Falling leaf (sketched angular velocity)</source>
        <translation>飘落的树叶（草图绘制的角速度）</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="463"/>
        <source>Pen (sketched angular speed)</source>
        <translation>笔（草图绘制的角速度大小）</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="464"/>
        <source>Pendulum (ScrewBender)</source>
        <translation>摆（ScrewBender）</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="465"/>
        <source>Spinning block (ScrewBender)</source>
        <translation>旋转的方块（ScrewBender）</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="466"/>
        <source>Critter&apos;s non-planar cycle (ScrewBender)</source>
        <translation>小动物的非平面循环（ScrewBender）</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="467"/>
        <source>Tossed T-handle (free flight)</source>
        <translation>抛出的 T 形手柄（自由飞行）</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="468"/>
        <source>Flipped coin (free flight)</source>
        <translation>抛起的硬币（自由飞行）</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="469"/>
        <source>Thrown book (free flight)</source>
        <translation>抛出的书（自由飞行）</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="488"/>
        <source>Save Project As</source>
        <translation>项目另存为</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="501"/>
        <source>Cannot save the project</source>
        <translation>无法保存项目</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="505"/>
        <source>Saved %1</source>
        <translation>已保存 %1</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="514"/>
        <source>Unsaved changes</source>
        <translation>未保存的更改</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="514"/>
        <source>The project has unsaved changes. Save them first?</source>
        <translation>项目有未保存的更改。要先保存吗？</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="553"/>
        <source>About Gyre</source>
        <translation>关于 Gyre</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="554"/>
        <source>&lt;h3&gt;Gyre %1&lt;/h3&gt;&lt;p&gt;Edit the rotations of animated rigid objects: every way of writing an orientation, interpolation that behaves, sketched angular velocity, and ScrewBender motions.&lt;/p&gt;&lt;p&gt;Built on Qt %2, Eigen %3.%4.%5, Ceres Solver %6, Assimp %7 and QCustomPlot %8.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Gyre %1&lt;/h3&gt;&lt;p&gt;编辑动画刚体的旋转：各种朝向表示方式、表现良好的插值、草图绘制的角速度，以及 ScrewBender 运动。&lt;/p&gt;&lt;p&gt;基于 Qt %2、Eigen %3.%4.%5、Ceres Solver %6、Assimp %7 和 QCustomPlot %8 构建。&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="574"/>
        <source>Autosave failed: %1</source>
        <translation>自动保存失败：%1</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="583"/>
        <source>an untitled project</source>
        <translation>一个未命名项目</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="586"/>
        <source>Recover unsaved work</source>
        <translation>恢复未保存的工作</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="587"/>
        <source>Gyre ended without saving changes to %1 (last copy %2). Recover them?</source>
        <translation>Gyre 结束时未保存对 %1 的更改（最后一次副本 %2）。要恢复吗？</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="602"/>
        <source>Cannot recover</source>
        <translation>无法恢复</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="577"/>
        <source>Autosave is off: %1</source>
        <translation>自动保存已关闭：%1</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="213"/>
        <source>Outliner</source>
        <translation>大纲</translation>
    </message>
</context>
<context>
    <name>gyre::app::MassPropertiesGroup</name>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="47"/>
        <source>Body</source>
        <translation>刚体</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="51"/>
        <source>Type values</source>
        <translation>输入数值</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="68"/>
        <source>Ixx</source>
        <translation>Ixx</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="68"/>
        <source>Iyy</source>
        <translation>Iyy</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="68"/>
        <source>Izz</source>
        <translation>Izz</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="68"/>
        <source>Ixy</source>
        <translation>Ixy</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="68"/>
        <source>Ixz</source>
        <translation>Ixz</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="68"/>
        <source>Iyz</source>
        <translation>Iyz</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="71"/>
        <source>mass</source>
        <translation>质量</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="72"/>
        <source>centre x</source>
        <translation>质心 x</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="72"/>
        <source>centre y</source>
        <translation>质心 y</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="72"/>
        <source>centre z</source>
        <translation>质心 z</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="78"/>
        <source>Mass (kg)</source>
        <translation>质量 (kg)</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="79"/>
        <source>Centre (m)</source>
        <translation>质心 (m)</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="80"/>
        <source>Inertia (kg·m²)</source>
        <translation>惯性 (kg·m²)</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="81"/>
        <source>Principal</source>
        <translation>主惯性矩</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="122"/>
        <source>%1, %2, %3 kg·m²</source>
        <translation>%1、%2、%3 kg·m²</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="156"/>
        <location filename="../src/app/mass_properties_group.cpp" line="168"/>
        <source>Not changed: %1</source>
        <translation>未更改：%1</translation>
    </message>
</context>
<context>
    <name>gyre::app::NumberFields</name>
    <message>
        <location filename="../src/app/number_fields.cpp" line="49"/>
        <source>Exact value: %1</source>
        <translation>精确值：%1</translation>
    </message>
</context>
<context>
    <name>gyre::app::OffscreenGlWidget</name>
    <message>
        <location filename="../src/app/viewport/offscreen_gl_widget.cpp" line="33"/>
        <source>The display could not make an offscreen surface for OpenGL.</source>
        <translation>显示系统无法为 OpenGL 创建离屏表面。</translation>
    </message>
    <message>
        <location filename="../src/app/viewport/offscreen_gl_widget.cpp" line="35"/>
        <source>The display could not make an OpenGL %1.%2 context.</source>
        <translation>显示系统无法创建 OpenGL %1.%2 上下文。</translation>
    </message>
    <message>
        <location filename="../src/app/viewport/offscreen_gl_widget.cpp" line="39"/>
        <source>The display could not make its OpenGL context current.</source>
        <translation>显示系统无法激活其 OpenGL 上下文。</translation>
    </message>
    <message>
        <location filename="../src/app/viewport/offscreen_gl_widget.cpp" line="73"/>
        <source>OpenGL could not make a framebuffer of %1 × %2 pixels.</source>
        <translation>OpenGL 无法创建 %1 × %2 像素的帧缓冲区。</translation>
    </message>
</context>
<context>
    <name>gyre::app::OutlinerPanel</name>
    <message>
        <location filename="../src/app/outliner/outliner_panel.cpp" line="28"/>
        <source>Filter by name</source>
        <translation>按名称筛选</translation>
    </message>
    <message numerus="yes">
        <location filename="../src/app/outliner/outliner_panel.cpp" line="141"/>
        <source>Delete %n Objects</source>
        <translation>
            <numerusform>删除 %n 个对象</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>gyre::app::PatternCanvas</name>
    <message>
        <location filename="../src/app/sketch/pattern_pad.cpp" line="34"/>
        <source>Draw the pattern once, left to right: x along the strokes, y across them</source>
        <translation>从左到右绘制一次图案：x 沿笔画方向，y 垂直于笔画</translation>
    </message>
</context>
<context>
    <name>gyre::app::PatternPad</name>
    <message>
        <location filename="../src/app/sketch/pattern_pad.cpp" line="146"/>
        <source>Clear Pattern</source>
        <translation>清除图案</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/pattern_pad.cpp" line="150"/>
        <source>off</source>
        <translation>关</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/pattern_pad.cpp" line="151"/>
        <source>How many times the pattern repeats along the direction curve; off: not applied</source>
        <translation>图案沿方向曲线重复的次数；关：不应用</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/pattern_pad.cpp" line="152"/>
        <source>Take the pattern away</source>
        <translation>移除图案</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/pattern_pad.cpp" line="153"/>
        <source>&amp;Repeat:</source>
        <translation>重复(&amp;R)：</translation>
    </message>
</context>
<context>
    <name>gyre::app::PreferencesDialog</name>
    <message>
        <location filename="../src/app/preferences_dialog.cpp" line="22"/>
        <source>System default</source>
        <translation>系统默认</translation>
    </message>
</context>
<context>
    <name>gyre::app::SceneFileActions</name>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="30"/>
        <source>Scenes (*.fbx *.gltf *.glb *.dae *.obj *.bvh *.3ds *.x *.ase *.ply *.stl);;All files (*)</source>
        <translation>场景 (*.fbx *.gltf *.glb *.dae *.obj *.bvh *.3ds *.x *.ase *.ply *.stl);;所有文件 (*)</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="36"/>
        <source>glTF 2.0 (*.gltf);;glTF 2.0 binary (*.glb);;Collada (*.dae);;FBX (*.fbx);;OBJ, meshes only (*.obj)</source>
        <translation>glTF 2.0 (*.gltf);;glTF 2.0 二进制 (*.glb);;Collada (*.dae);;FBX (*.fbx);;OBJ，仅网格 (*.obj)</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="63"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="80"/>
        <location filename="../src/app/scene_file_actions.cpp" line="147"/>
        <source>Import of %1 cancelled</source>
        <translation>已取消导入 %1</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="86"/>
        <source>Import Scene</source>
        <translation>导入场景</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="94"/>
        <source>Export Scene</source>
        <translation>导出场景</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="108"/>
        <location filename="../src/app/scene_file_actions.cpp" line="119"/>
        <location filename="../src/app/scene_file_actions.cpp" line="165"/>
        <source>Wait for the scene file being read or written first</source>
        <translation>请先等待正在读取或写入的场景文件完成</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="122"/>
        <source>Importing %1…</source>
        <translation>正在导入 %1…</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="157"/>
        <source>Cannot export</source>
        <translation>无法导出</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="158"/>
        <source>%1: Gyre writes .gltf, .glb, .dae, .fbx and .obj scenes; the file name&apos;s extension says which.</source>
        <translation>%1：Gyre 可写出 .gltf、.glb、.dae、.fbx 和 .obj 场景；由文件扩展名决定格式。</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="168"/>
        <source>Exporting %1…</source>
        <translation>正在导出 %1…</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="175"/>
        <source>%1: the file holds no objects.</source>
        <translation>%1：文件不含任何对象。</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="178"/>
        <source>Import %1</source>
        <translation>导入 %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../src/app/scene_file_actions.cpp" line="197"/>
        <source>Objects imported from %1: %n</source>
        <translation>
            <numerusform>已从 %1 导入 %n 个对象</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="200"/>
        <source>Imported %1</source>
        <translation>已导入 %1</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="206"/>
        <location filename="../src/app/scene_file_actions.cpp" line="207"/>
        <source>Exported %1</source>
        <translation>已导出 %1</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="213"/>
        <source>Scene file</source>
        <translation>场景文件</translation>
    </message>
    <message numerus="yes">
        <location filename="../src/app/scene_file_actions.cpp" line="222"/>
        <source>Done. Warnings about what the file could not keep: %n.</source>
        <translation>
            <numerusform>已完成，有 %n 条关于文件无法保留内容的警告。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>gyre::app::SceneTreeModel</name>
    <message>
        <location filename="../src/app/outliner/scene_tree_model.cpp" line="135"/>
        <source>Shown in the viewport: uncheck to hide it</source>
        <translation>在视口中显示：取消勾选以隐藏</translation>
    </message>
    <message>
        <location filename="../src/app/outliner/scene_tree_model.cpp" line="135"/>
        <source>Hidden in the viewport: check to show it</source>
        <translation>在视口中隐藏：勾选以显示</translation>
    </message>
    <message numerus="yes">
        <location filename="../src/app/outliner/scene_tree_model.cpp" line="309"/>
        <source>Reparent %n Objects in Place</source>
        <translation>
            <numerusform>原位更改 %n 个对象的父级</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>gyre::app::ScrewBenderPanel</name>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="26"/>
        <source>Slerp (great arcs)</source>
        <translation>Slerp（大圆弧）</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="28"/>
        <source>Nlerp (normalised straight lines)</source>
        <translation>Nlerp（归一化直线）</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="30"/>
        <source>Squad (smooth quaternion curve)</source>
        <translation>Squad（平滑四元数曲线）</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="32"/>
        <source>Hermite quaternion spline</source>
        <translation>Hermite 四元数样条</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="34"/>
        <source>Euler angles, linearly</source>
        <translation>欧拉角，线性</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="36"/>
        <source>Euler angles, smooth (automatic tangents)</source>
        <translation>欧拉角，平滑（自动切线）</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="38"/>
        <source>Screw motion (ScrewBender)</source>
        <translation>螺旋运动（ScrewBender）</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="40"/>
        <source>Ballistic (free flight between keys)</source>
        <translation>弹道（关键帧之间自由飞行）</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="50"/>
        <source>Four-point</source>
        <translation>四点</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="52"/>
        <source>Four-point B</source>
        <translation>四点 B</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="54"/>
        <source>Cubic B-spline</source>
        <translation>三次 B 样条</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="56"/>
        <source>Jarek</source>
        <translation>Jarek</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="146"/>
        <source>%1 from %2 keyframes</source>
        <translation>%1，来自 %2 个关键帧</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="147"/>
        <source>too many to hold, from %1 keyframes</source>
        <translation>过多无法容纳，来自 %1 个关键帧</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="159"/>
        <source>The interpolation was not changed: %1.</source>
        <translation>插值未更改：%1。</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="172"/>
        <source>Interpolate by Screws</source>
        <translation>以螺旋运动插值</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="196"/>
        <source>The subdivision was not changed: %1.</source>
        <translation>细分未更改：%1。</translation>
    </message>
</context>
<context>
    <name>gyre::app::SmoothnessPanel</name>
    <message>
        <location filename="../src/app/smoothness_panel.cpp" line="29"/>
        <source>position
(units)</source>
        <translation>位置
（单位）</translation>
    </message>
    <message>
        <location filename="../src/app/smoothness_panel.cpp" line="31"/>
        <source>velocity
(units/s)</source>
        <translation>速度
（单位/秒）</translation>
    </message>
    <message>
        <location filename="../src/app/smoothness_panel.cpp" line="33"/>
        <source>acceleration
(units/s²)</source>
        <translation>加速度
（单位/秒²）</translation>
    </message>
    <message>
        <location filename="../src/app/smoothness_panel.cpp" line="42"/>
        <location filename="../src/app/smoothness_panel.cpp" line="108"/>
        <source>x</source>
        <translation>x</translation>
    </message>
    <message>
        <location filename="../src/app/smoothness_panel.cpp" line="44"/>
        <location filename="../src/app/smoothness_panel.cpp" line="108"/>
        <source>y</source>
        <translation>y</translation>
    </message>
    <message>
        <location filename="../src/app/smoothness_panel.cpp" line="46"/>
        <location filename="../src/app/smoothness_panel.cpp" line="108"/>
        <source>z</source>
        <translation>z</translation>
    </message>
    <message>
        <location filename="../src/app/smoothness_panel.cpp" line="48"/>
        <source>magnitude</source>
        <translation>大小</translation>
    </message>
    <message>
        <location filename="../src/app/smoothness_panel.cpp" line="106"/>
        <source>Point of the object (local):</source>
        <translation>对象上的点（局部）：</translation>
    </message>
    <message>
        <location filename="../src/app/smoothness_panel.cpp" line="113"/>
        <source>%1 </source>
        <translation>%1 </translation>
    </message>
    <message>
        <location filename="../src/app/smoothness_panel.cpp" line="116"/>
        <source>The %1 coordinate of the plotted point, in the object&apos;s frame</source>
        <translation>所绘制点在对象坐标系中的 %1 坐标</translation>
    </message>
    <message>
        <location filename="../src/app/smoothness_panel.cpp" line="164"/>
        <source>time (s)</source>
        <translation>时间（秒）</translation>
    </message>
</context>
<context>
    <name>gyre::app::SphereView</name>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="192"/>
        <source>Draw</source>
        <translation>绘制</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="193"/>
        <source>Draw the direction of the angular velocity on the front of the sphere</source>
        <translation>在球的正面绘制角速度的方向</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="194"/>
        <source>Erase</source>
        <translation>擦除</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="194"/>
        <source>Erase the strokes&apos; points under the pointer</source>
        <translation>擦除指针下的笔画点</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="195"/>
        <source>Pattern</source>
        <translation>图案</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="196"/>
        <source>Draw a pattern to repeat along the strokes, on the pad</source>
        <translation>在画板上绘制沿笔画重复的图案</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="199"/>
        <source>Reset View</source>
        <translation>重置视图</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="202"/>
        <source>Turn the sphere back to its first view, z up (R)</source>
        <translation>将球转回初始视图，z 朝上（R）</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="246"/>
        <source>Select an object to sketch the direction of its angular velocity.</source>
        <translation>选择一个对象以绘制其角速度方向的草图。</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="248"/>
        <source>%1 does not turn: key it in two orientations to give it an angular velocity to sketch.</source>
        <translation>%1 没有转动：请在两个朝向上设置关键帧，使其具有可绘制的角速度。</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="623"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="656"/>
        <source>motion: ω/|ω|</source>
        <translation>运动：ω/|ω|</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="658"/>
        <source>fitted</source>
        <translation>拟合后</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="659"/>
        <source>before the fit</source>
        <translation>拟合前</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="661"/>
        <source>sketch as drawn</source>
        <translation>绘制的草图</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="662"/>
        <source>sketch as fitted, pattern applied</source>
        <translation>拟合后的草图，已应用图案</translation>
    </message>
</context>
<context>
    <name>gyre::app::TimeBar</name>
    <message>
        <location filename="../src/app/time_bar.cpp" line="29"/>
        <source> s</source>
        <translation> 秒</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="50"/>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="57"/>
        <source> m/s²</source>
        <translation> m/s²</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="60"/>
        <source>How fast the centre of mass of a ballistic track falls</source>
        <translation>弹道轨迹的质心下落的快慢</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="62"/>
        <source>+X</source>
        <translation>+X</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="62"/>
        <source>−X</source>
        <translation>−X</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="62"/>
        <source>+Y</source>
        <translation>+Y</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="62"/>
        <source>−Y</source>
        <translation>−Y</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="62"/>
        <source>+Z</source>
        <translation>+Z</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="62"/>
        <source>−Z</source>
        <translation>−Z</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="64"/>
        <source>The scene&apos;s up axis: gravity pulls the other way</source>
        <translation>场景的向上轴：重力指向相反方向</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="67"/>
        <source>Frames per second</source>
        <translation>每秒帧数</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="68"/>
        <source>Where the scene starts</source>
        <translation>场景的开始时间</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="69"/>
        <source>Where the scene ends</source>
        <translation>场景的结束时间</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="71"/>
        <location filename="../src/app/time_bar.cpp" line="113"/>
        <source>Time %1 s</source>
        <translation>时间 %1 秒</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="72"/>
        <location filename="../src/app/time_bar.cpp" line="115"/>
        <source>Frame %1</source>
        <translation>第 %1 帧</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="79"/>
        <source>Rate</source>
        <translation>帧率</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="79"/>
        <source>Start</source>
        <translation>开始</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="80"/>
        <source>End</source>
        <translation>结束</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="80"/>
        <source>Gravity</source>
        <translation>重力</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="81"/>
        <source>Up</source>
        <translation>向上</translation>
    </message>
</context>
<context>
    <name>gyre::app::TimelineWidget</name>
    <message>
        <location filename="../src/app/timeline_widget.cpp" line="93"/>
        <location filename="../src/app/timeline_widget.cpp" line="275"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../src/app/timeline_widget.cpp" line="98"/>
        <source>%1 f</source>
        <translation>%1 帧</translation>
    </message>
</context>
<context>
    <name>gyre::app::Translations</name>
    <message>
        <location filename="../src/app/language.cpp" line="59"/>
        <source>Gyre does not speak the language &quot;%1&quot; and speaks English instead.</source>
        <translation>Gyre 不支持语言“%1”，将改用英语。</translation>
    </message>
</context>
<context>
    <name>gyre::app::ViewPreferences</name>
    <message>
        <location filename="../src/app/view_preferences.cpp" line="61"/>
        <source>Trail</source>
        <translation>轨迹</translation>
    </message>
    <message numerus="yes">
        <location filename="../src/app/view_preferences.cpp" line="65"/>
        <source>%n Copies</source>
        <translation>
            <numerusform>%n 个副本</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../src/app/view_preferences.cpp" line="68"/>
        <source>Over the Whole Range</source>
        <translation>覆盖整个范围</translation>
    </message>
    <message numerus="yes">
        <location filename="../src/app/view_preferences.cpp" line="68"/>
        <source>Every %n Frame(s) About the Current Frame</source>
        <translation>
            <numerusform>当前帧前后每 %n 帧</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../src/app/view_preferences.cpp" line="71"/>
        <source>Y Up</source>
        <translation>Y 向上</translation>
    </message>
    <message>
        <location filename="../src/app/view_preferences.cpp" line="74"/>
        <source>Show the scene with y up, as Maya does: orbit about y, the grid across it, the front view along −z</source>
        <translation>像 Maya 一样以 y 向上显示场景：绕 y 旋转，网格与其垂直，前视图沿 −z</translation>
    </message>
</context>
<context>
    <name>gyre::model::Command</name>
    <message>
        <location filename="../src/model/commands/add_stroke_command.cpp" line="11"/>
        <source>Add Stroke</source>
        <translation>添加笔画</translation>
    </message>
    <message>
        <location filename="../src/model/commands/apply_fit_result_command.cpp" line="53"/>
        <source>Apply angular velocity fit</source>
        <translation>应用角速度拟合</translation>
    </message>
    <message>
        <location filename="../src/model/commands/remove_fit_command.cpp" line="20"/>
        <source>Remove angular velocity fit</source>
        <translation>移除角速度拟合</translation>
    </message>
    <message>
        <location filename="../src/model/commands/delete_object_command.cpp" line="25"/>
        <source>Delete Object</source>
        <translation>删除对象</translation>
    </message>
    <message>
        <location filename="../src/model/commands/edit_stroke_command.cpp" line="11"/>
        <source>Edit Stroke</source>
        <translation>编辑笔画</translation>
    </message>
    <message>
        <location filename="../src/model/commands/erase_stroke_command.cpp" line="9"/>
        <source>Erase Stroke</source>
        <translation>擦除笔画</translation>
    </message>
    <message>
        <location filename="../src/model/commands/import_objects_command.cpp" line="95"/>
        <source>Import Objects</source>
        <translation>导入对象</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_keyframe_time_command.cpp" line="33"/>
        <source>Move Keyframe</source>
        <translation>移动关键帧</translation>
    </message>
    <message>
        <location filename="../src/model/commands/rename_object_command.cpp" line="10"/>
        <source>Rename Object</source>
        <translation>重命名对象</translation>
    </message>
    <message>
        <location filename="../src/model/commands/reparent_object_command.cpp" line="34"/>
        <source>Reparent Object</source>
        <translation>更改对象的父级</translation>
    </message>
    <message>
        <location filename="../src/model/commands/retime_keyframes_command.cpp" line="43"/>
        <source>Retime Keyframes</source>
        <translation>重新调整关键帧时间</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_fit_parameter_command.cpp" line="25"/>
        <source>Set Fit Parameter</source>
        <translation>设置拟合参数</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_fit_window_command.cpp" line="11"/>
        <source>Set Fit Window</source>
        <translation>设置拟合窗口</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_interpolation_command.cpp" line="28"/>
        <source>Set Interpolation</source>
        <translation>设置插值</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_keyframe_orientation_command.cpp" line="37"/>
        <location filename="../src/model/commands/set_keyframe_orientation_command.cpp" line="45"/>
        <source>Rotate Keyframe</source>
        <translation>旋转关键帧</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_keyframe_position_command.cpp" line="11"/>
        <source>Move Keyframe Position</source>
        <translation>移动关键帧位置</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_magnitude_curve_command.cpp" line="11"/>
        <source>Draw Magnitude Curve</source>
        <translation>绘制大小曲线</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_pattern_command.cpp" line="21"/>
        <source>Draw Pattern</source>
        <translation>绘制图案</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_subdivision_command.cpp" line="24"/>
        <source>Set Subdivision</source>
        <translation>设置细分</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_time_range_command.cpp" line="20"/>
        <source>Set Time Range</source>
        <translation>设置时间范围</translation>
    </message>
    <message>
        <location filename="../src/model/commands/toggle_keyframe_constraint_command.cpp" line="10"/>
        <source>Toggle Keyframe Constraint</source>
        <translation>切换关键帧约束</translation>
    </message>
    <message>
        <location filename="../src/model/commands/reparent_object_in_place_command.cpp" line="30"/>
        <source>Reparent Object in Place</source>
        <translation>原位更改对象的父级</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_object_visibility_command.cpp" line="10"/>
        <source>Show Object</source>
        <translation>显示对象</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_object_visibility_command.cpp" line="11"/>
        <source>Hide Object</source>
        <translation>隐藏对象</translation>
    </message>
    <message>
        <location filename="../src/model/commands/apply_euler_filter_command.cpp" line="15"/>
        <source>Apply Euler Filter</source>
        <translation>应用欧拉滤波器</translation>
    </message>
    <message>
        <location filename="../src/model/commands/replace_keyframes_command.cpp" line="21"/>
        <source>Delete Keyframes</source>
        <translation>删除关键帧</translation>
    </message>
    <message>
        <location filename="../src/model/commands/replace_keyframes_command.cpp" line="23"/>
        <source>Insert Keyframes</source>
        <translation>插入关键帧</translation>
    </message>
    <message>
        <location filename="../src/model/commands/replace_keyframes_command.cpp" line="25"/>
        <source>Paste Keyframes</source>
        <translation>粘贴关键帧</translation>
    </message>
    <message>
        <location filename="../src/model/commands/replace_keyframes_command.cpp" line="27"/>
        <source>Move Keyframes</source>
        <translation>移动关键帧</translation>
    </message>
    <message>
        <location filename="../src/model/commands/replace_keyframes_command.cpp" line="31"/>
        <source>Scale Keyframes</source>
        <translation>缩放关键帧</translation>
    </message>
    <message>
        <location filename="../src/model/commands/step_ballistic_solution_command.cpp" line="31"/>
        <source>Step Flight Solution</source>
        <translation>切换飞行解</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_mass_override_command.cpp" line="14"/>
        <source>Set Mass Properties</source>
        <translation>设置质量属性</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_mass_override_command.cpp" line="15"/>
        <source>Mass From Mesh</source>
        <translation>由网格计算质量</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_rotation_mode_command.cpp" line="22"/>
        <source>Set Rotation Mode</source>
        <translation>设置旋转模式</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_physics_target_command.cpp" line="25"/>
        <source>Set Physics Target</source>
        <translation>设置物理目标</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_gravity_command.cpp" line="10"/>
        <source>Set Gravity</source>
        <translation>设置重力</translation>
    </message>
</context>
<context>
    <name>gyre::model::Primitive</name>
    <message>
        <location filename="../src/model/primitive_meshes.cpp" line="166"/>
        <source>Block</source>
        <translation>方块</translation>
    </message>
    <message>
        <location filename="../src/model/primitive_meshes.cpp" line="168"/>
        <source>Box</source>
        <translation>立方体</translation>
    </message>
    <message>
        <location filename="../src/model/primitive_meshes.cpp" line="170"/>
        <source>Disc</source>
        <translation>圆盘</translation>
    </message>
    <message>
        <location filename="../src/model/primitive_meshes.cpp" line="172"/>
        <source>Cone</source>
        <translation>圆锥</translation>
    </message>
    <message>
        <location filename="../src/model/primitive_meshes.cpp" line="174"/>
        <source>Arrow</source>
        <translation>箭头</translation>
    </message>
</context>
<context>
    <name>gyre::model::SketchFitError</name>
    <message>
        <location filename="../src/model/sketch_fit_problem.cpp" line="95"/>
        <source>Direction stroke %1 cannot be followed: %2</source>
        <translation>无法沿方向笔画 %1 拟合：%2</translation>
    </message>
    <message>
        <location filename="../src/model/sketch_fit_problem.cpp" line="243"/>
        <source>The fit needs at least two keyframes on the selected object.</source>
        <translation>拟合需要所选对象至少有两个关键帧。</translation>
    </message>
    <message>
        <location filename="../src/model/sketch_fit_problem.cpp" line="246"/>
        <source>Nothing is sketched yet: draw the direction of the angular velocity on the sphere, or its magnitude on the plot.</source>
        <translation>尚未绘制草图：请在球面上绘制角速度的方向，或在图中绘制其大小。</translation>
    </message>
    <message>
        <location filename="../src/model/sketch_fit_problem.cpp" line="251"/>
        <source>The edit window has no length inside the keys&apos; span: widen it, or sketch between the first and the last key.</source>
        <translation>编辑窗口在关键帧范围内的长度为零：请扩大它，或在第一个和最后一个关键帧之间绘制草图。</translation>
    </message>
    <message>
        <location filename="../src/model/sketch_fit_problem.cpp" line="257"/>
        <source>The edit window of %1 s needs %2 target samples at %3 a second; the budget is %4: narrow the window.</source>
        <translation>%1 秒的编辑窗口在每秒 %3 个采样时需要 %2 个目标采样；上限为 %4：请缩小窗口。</translation>
    </message>
    <message>
        <location filename="../src/model/sketch_fit_problem.cpp" line="268"/>
        <source>The pattern cannot be repeated: %1</source>
        <translation>图案无法重复：%1</translation>
    </message>
    <message>
        <location filename="../src/model/physics_target.cpp" line="27"/>
        <source>the physics target needs at least two keyframes</source>
        <translation>物理目标至少需要两个关键帧</translation>
    </message>
    <message>
        <location filename="../src/model/physics_target.cpp" line="35"/>
        <source>the object is at rest at %1 s, so a free flight from there has no direction</source>
        <translation>物体在 %1 秒时静止，因此从该处出发的自由飞行没有方向</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../src/app/main.cpp" line="26"/>
        <source>%1: cannot write the screenshot</source>
        <translation>%1：无法写入截图</translation>
    </message>
    <message>
        <location filename="../src/app/main.cpp" line="53"/>
        <source>Edit the rotations of animated rigid objects.</source>
        <translation>编辑动画刚体的旋转。</translation>
    </message>
    <message>
        <location filename="../src/app/main.cpp" line="58"/>
        <source>A Gyre project to open, or a scene file (FBX, glTF, ...) to import.</source>
        <translation>要打开的 Gyre 项目，或要导入的场景文件（FBX、glTF 等）。</translation>
    </message>
    <message>
        <location filename="../src/app/main.cpp" line="61"/>
        <source>Save a picture of the window to &lt;file&gt; after a few seconds, then quit.</source>
        <translation>几秒后将窗口截图保存到 &lt;file&gt;，然后退出。</translation>
    </message>
    <message>
        <location filename="../src/app/main.cpp" line="64"/>
        <source>Wait &lt;ms&gt; milliseconds before the screenshot.</source>
        <translation>截图前等待 &lt;ms&gt; 毫秒。</translation>
    </message>
    <message>
        <location filename="../src/app/main.cpp" line="68"/>
        <source>Speak &lt;language&gt; (%1) instead of the one chosen in the preferences.</source>
        <translation>使用 &lt;language&gt;（%1），而不是首选项中选择的语言。</translation>
    </message>
    <message>
        <location filename="../src/app/main.cpp" line="76"/>
        <source>--delay takes a number of milliseconds, not &quot;%1&quot;.</source>
        <translation>--delay 需要毫秒数，而不是“%1”。</translation>
    </message>
    <message>
        <location filename="../src/app/main.cpp" line="79"/>
        <source>give at most one file to open.</source>
        <translation>最多只能指定一个要打开的文件。</translation>
    </message>
</context>
</TS>
