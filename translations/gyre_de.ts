<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>FitPanel</name>
    <message>
        <location filename="../ui/fit_panel.ui" line="9"/>
        <source>Select an object to fit its rotation to the sketched angular velocity.</source>
        <translation>Wählen Sie ein Objekt, um seine Rotation an die skizzierte Winkelgeschwindigkeit anzupassen.</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="41"/>
        <source>Energy E = αW_T + βW_A</source>
        <translation>Energie E = αW_T + βW_A</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="45"/>
        <source>&amp;α (smoothness)</source>
        <translation>&amp;α (Glätte)</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="51"/>
        <source>Weight of the tangential acceleration W_T: larger is smoother, further from the sketch. The paper uses 0.001–0.005.</source>
        <translation>Gewicht der Tangentialbeschleunigung W_T: größer ist glatter, aber weiter von der Skizze entfernt. Der Artikel verwendet 0,001–0,005.</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="61"/>
        <source>&amp;β (follow the sketch)</source>
        <translation>&amp;β (der Skizze folgen)</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="67"/>
        <source>Weight of W_A, the deviation of the angular velocity from the sketch</source>
        <translation>Gewicht von W_A, der Abweichung der Winkelgeschwindigkeit von der Skizze</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="77"/>
        <source>&amp;δ</source>
        <translation>&amp;δ</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="83"/>
        <source>The largest error accepted on a fragment of the window, measured in the target&apos;s own mean squared speed (F_n/S̄, in seconds); above it the fit inserts variable frames</source>
        <translation>Der größte zulässige Fehler auf einem Abschnitt des Fensters, gemessen an der mittleren quadratischen Geschwindigkeit des Ziels (F_n/S̄, in Sekunden); darüber fügt die Anpassung variable Frames ein</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="96"/>
        <source>Edited window</source>
        <translation>Bearbeitetes Fenster</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="100"/>
        <source>&amp;Whole sketch</source>
        <translation>&amp;Ganze Skizze</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="101"/>
        <source>Refit the span the sketch covers; clear to choose the window</source>
        <translation>Den Bereich neu anpassen, den die Skizze abdeckt; abwählen, um das Fenster selbst zu wählen</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="106"/>
        <source>&amp;Start</source>
        <translation>&amp;Anfang</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="112"/>
        <source>Where the refitted span begins</source>
        <translation>Wo der neu angepasste Bereich beginnt</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="115"/>
        <location filename="../ui/fit_panel.ui" line="130"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="121"/>
        <source>E&amp;nd</source>
        <translation>&amp;Ende</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="127"/>
        <source>Where the refitted span ends</source>
        <translation>Wo der neu angepasste Bereich endet</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="139"/>
        <source>Keyframes kept exactly</source>
        <translation>Exakt gehaltene Schlüsselbilder</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="143"/>
        <source>A checked key keeps its orientation; the fit may turn a cleared one</source>
        <translation>Ein angehaktes Schlüsselbild behält seine Orientierung; ein nicht angehaktes darf die Anpassung drehen</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="149"/>
        <source>Time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="150"/>
        <source>Constrained</source>
        <translation>Fixiert</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="158"/>
        <source>Set &amp;physics target</source>
        <translation>&amp;Physikziel setzen</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="159"/>
        <source>Replace the sketch by the angular velocity of a free flight from where the motion is at the edit window&apos;s start; Fit then bends the motion toward it and keeps the constrained keys</source>
        <translation>Die Skizze durch die Winkelgeschwindigkeit eines freien Flugs ab dem Zustand der Bewegung am Anfang des Bearbeitungsfensters ersetzen; Anpassen biegt die Bewegung dann dorthin und behält die festgelegten Keys</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="166"/>
        <source>Fit</source>
        <translation>Anpassen</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="167"/>
        <source>Fit the rotation to the sketch (Ctrl+F)</source>
        <translation>Die Rotation an die Skizze anpassen (Ctrl+F)</translation>
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
        <translation>&amp;Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="174"/>
        <source>Stop the running fit; the motion stays as it is</source>
        <translation>Die laufende Anpassung anhalten; die Bewegung bleibt, wie sie ist</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="179"/>
        <source>&amp;Remove fit</source>
        <translation>Anpassung &amp;entfernen</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="180"/>
        <source>Go back to the interpolation through the keys</source>
        <translation>Zur Interpolation durch die Schlüsselbilder zurückkehren</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="187"/>
        <source>&amp;Live: refit while the sketch changes</source>
        <translation>&amp;Live: bei jeder Änderung der Skizze neu anpassen</translation>
    </message>
    <message>
        <location filename="../ui/fit_panel.ui" line="188"/>
        <source>Refit at every change of the sketch, keys or settings; while drawing, the view previews the fit</source>
        <translation>Bei jeder Änderung der Skizze, der Schlüsselbilder oder der Einstellungen neu anpassen; beim Zeichnen zeigt die Ansicht eine Vorschau der Anpassung</translation>
    </message>
</context>
<context>
    <name>InspectorWidget</name>
    <message>
        <location filename="../ui/inspector_widget.ui" line="9"/>
        <source>Select a keyframe on the timeline or in the viewport to inspect it.</source>
        <translation>Wählen Sie ein Schlüsselbild in der Zeitleiste oder im Ansichtsfenster, um es zu untersuchen.</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="52"/>
        <source>Rotation Mode</source>
        <translation>Rotationsmodus</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="56"/>
        <source>&amp;Keys store</source>
        <translation>&amp;Keys speichern</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="62"/>
        <source>Quaternion keys store orientations; Euler keys store the three angles as typed, so 0° then 360° is a full turn, and interpolate them in the object&apos;s order</source>
        <translation>Quaternion-Keys speichern Orientierungen; Euler-Keys speichern die drei Winkel wie eingegeben, sodass 0° und dann 360° eine volle Umdrehung ist, und interpolieren sie in der Reihenfolge des Objekts</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="92"/>
        <source>Keyframe</source>
        <translation>Schlüsselbild</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="96"/>
        <source>&amp;Time (s)</source>
        <translation>&amp;Zeit (s)</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="102"/>
        <source>Time in seconds</source>
        <translation>Zeit in Sekunden</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="107"/>
        <source>&amp;Constrained: the fit keeps this key exactly</source>
        <translation>&amp;Fixiert: die Anpassung hält dieses Schlüsselbild exakt</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="115"/>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="137"/>
        <source>Position x</source>
        <translation>Position x</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="142"/>
        <source>Position y</source>
        <translation>Position y</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="147"/>
        <source>Position z</source>
        <translation>Position z</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="155"/>
        <source>Quaternion</source>
        <translation>Quaternion</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="183"/>
        <source>Quaternion w</source>
        <translation>Quaternion w</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="188"/>
        <source>Quaternion x</source>
        <translation>Quaternion x</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="193"/>
        <source>Quaternion y</source>
        <translation>Quaternion y</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="198"/>
        <source>Quaternion z</source>
        <translation>Quaternion z</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="206"/>
        <source>Rotation matrix</source>
        <translation>Rotationsmatrix</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="210"/>
        <source>Matrix row 1, column 1</source>
        <translation>Matrix Zeile 1, Spalte 1</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="215"/>
        <source>Matrix row 1, column 2</source>
        <translation>Matrix Zeile 1, Spalte 2</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="220"/>
        <source>Matrix row 1, column 3</source>
        <translation>Matrix Zeile 1, Spalte 3</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="225"/>
        <source>Matrix row 2, column 1</source>
        <translation>Matrix Zeile 2, Spalte 1</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="230"/>
        <source>Matrix row 2, column 2</source>
        <translation>Matrix Zeile 2, Spalte 2</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="235"/>
        <source>Matrix row 2, column 3</source>
        <translation>Matrix Zeile 2, Spalte 3</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="240"/>
        <source>Matrix row 3, column 1</source>
        <translation>Matrix Zeile 3, Spalte 1</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="245"/>
        <source>Matrix row 3, column 2</source>
        <translation>Matrix Zeile 3, Spalte 2</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="250"/>
        <source>Matrix row 3, column 3</source>
        <translation>Matrix Zeile 3, Spalte 3</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="258"/>
        <source>Axis-angle</source>
        <translation>Achse-Winkel</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="262"/>
        <source>axis x</source>
        <translation>Achse x</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="268"/>
        <source>axis y</source>
        <translation>Achse y</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="274"/>
        <source>axis z</source>
        <translation>Achse z</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="280"/>
        <source>angle (°)</source>
        <translation>Winkel (°)</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="286"/>
        <source>Axis x</source>
        <translation>Achse x</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="291"/>
        <source>Axis y</source>
        <translation>Achse y</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="296"/>
        <source>Axis z</source>
        <translation>Achse z</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="301"/>
        <source>Angle in degrees</source>
        <translation>Winkel in Grad</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="309"/>
        <source>Euler angles</source>
        <translation>Euler-Winkel</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="70"/>
        <source>&amp;Order</source>
        <translation>&amp;Reihenfolge</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="76"/>
        <source>The axes the three angles turn about, first to last</source>
        <translation>Die Achsen, um die die drei Winkel drehen, vom ersten bis zum letzten</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="81"/>
        <source>Extrinsic angles turn about the fixed world axes; intrinsic ones about the axes as they have been turned so far</source>
        <translation>Extrinsische Winkel drehen um die festen Weltachsen, intrinsische um die Achsen, wie sie bis dahin gedreht wurden</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="328"/>
        <source>Euler angle 1 in degrees</source>
        <translation>Euler-Winkel 1 in Grad</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="333"/>
        <source>Euler angle 2 in degrees</source>
        <translation>Euler-Winkel 2 in Grad</translation>
    </message>
    <message>
        <location filename="../ui/inspector_widget.ui" line="338"/>
        <source>Euler angle 3 in degrees</source>
        <translation>Euler-Winkel 3 in Grad</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <location filename="../ui/main_window.ui" line="18"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="19"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="20"/>
        <source>Open Sa&amp;mple</source>
        <translation>Beis&amp;piel öffnen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="34"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="45"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="46"/>
        <source>&amp;Panels</source>
        <translation>Bedien&amp;felder</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="71"/>
        <source>&amp;Motion</source>
        <translation>Be&amp;wegung</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="88"/>
        <source>&amp;Object</source>
        <translation>&amp;Objekt</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="89"/>
        <source>&amp;Add</source>
        <translation>&amp;Hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="93"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="104"/>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="112"/>
        <source>Edit</source>
        <translation>Bearbeiten</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="117"/>
        <source>Playback</source>
        <translation>Wiedergabe</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="129"/>
        <source>Inspector</source>
        <translation>Inspektor</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="141"/>
        <source>ScrewBender</source>
        <translation>ScrewBender</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="153"/>
        <source>Undo History</source>
        <translation>Rückgängig-Verlauf</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="165"/>
        <source>Timeline</source>
        <translation>Zeitleiste</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="177"/>
        <source>Smoothness</source>
        <translation>Glätte</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="189"/>
        <source>Angular Velocity Direction</source>
        <translation>Richtung der Winkelgeschwindigkeit</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="201"/>
        <source>Fit</source>
        <translation>Anpassung</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="213"/>
        <source>Angular Speed</source>
        <translation>Betrag der Winkelgeschwindigkeit</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="225"/>
        <source>Graph Editor</source>
        <translation>Grapheneditor</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="237"/>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="238"/>
        <source>Start a new, empty project</source>
        <translation>Ein neues, leeres Projekt beginnen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="241"/>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="242"/>
        <source>Open a Gyre project</source>
        <translation>Ein Gyre-Projekt öffnen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="245"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="246"/>
        <source>Save the project</source>
        <translation>Das Projekt speichern</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="249"/>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="250"/>
        <source>Save the project under a new name</source>
        <translation>Das Projekt unter einem neuen Namen speichern</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="253"/>
        <source>&amp;Import Scene…</source>
        <translation>Szene &amp;importieren…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="254"/>
        <source>Add the objects and motion of an FBX, glTF, Collada, OBJ, BVH or other scene file</source>
        <translation>Die Objekte und die Bewegung einer FBX-, glTF-, Collada-, OBJ-, BVH- oder anderen Szenendatei hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="258"/>
        <source>&amp;Export Scene…</source>
        <translation>Szene &amp;exportieren…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="259"/>
        <source>Write the scene with its motion baked to glTF, Collada, FBX or OBJ</source>
        <translation>Die Szene mit gebackener Bewegung als glTF, Collada, FBX oder OBJ schreiben</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="263"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="264"/>
        <source>Quit Gyre</source>
        <translation>Gyre beenden</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="268"/>
        <source>Undo &amp;History</source>
        <translation>Rückgängig-&amp;Verlauf</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="269"/>
        <source>Show every step of the undo history</source>
        <translation>Jeden Schritt des Rückgängig-Verlaufs zeigen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="273"/>
        <source>&amp;Preferences…</source>
        <translation>&amp;Einstellungen…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="274"/>
        <source>Choose the language Gyre speaks</source>
        <translation>Die Sprache wählen, die Gyre spricht</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="280"/>
        <source>Original Motion as &amp;Ghost</source>
        <translation>Ursprüngliche Bewegung als &amp;Geisterbild</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="281"/>
        <source>Show the motion as it was when the project was opened or saved, faintly</source>
        <translation>Die Bewegung blass zeigen, wie sie beim Öffnen oder Speichern des Projekts war</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="286"/>
        <source>Centre &amp;Trajectory</source>
        <translation>&amp;Bahn des Mittelpunkts</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="287"/>
        <source>Show the path of the selected object&apos;s centre</source>
        <translation>Die Bahn des Mittelpunkts des gewählten Objekts zeigen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="292"/>
        <source>&amp;Control Poses</source>
        <translation>&amp;Kontrollposen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="293"/>
        <source>Show the keyframe poses of the selected object in place</source>
        <translation>Die Posen der Schlüsselbilder des gewählten Objekts an Ort und Stelle zeigen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="298"/>
        <source>&amp;Stroboscopic Trail</source>
        <translation>&amp;Stroboskopspur</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="299"/>
        <source>Show many copies of the selected object along its subdivided motion</source>
        <translation>Viele Kopien des gewählten Objekts entlang seiner unterteilten Bewegung zeigen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="303"/>
        <source>Angular &amp;Momentum</source>
        <translation>Dreh&amp;impuls</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="304"/>
        <source>Show the selected object&apos;s angular momentum as an arrow from its centre of mass: in free flight it stands still</source>
        <translation>Den Drehimpuls des ausgewählten Objekts als Pfeil vom Schwerpunkt zeigen: im freien Flug steht er still</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="308"/>
        <source>Pri&amp;ncipal Axes</source>
        <translation>Hau&amp;ptträgheitsachsen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="309"/>
        <source>Show the selected object&apos;s principal axes of inertia through its centre of mass</source>
        <translation>Die Hauptträgheitsachsen des ausgewählten Objekts durch seinen Schwerpunkt zeigen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="312"/>
        <source>&amp;Frame Scene</source>
        <translation>Szene ein&amp;passen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="313"/>
        <source>Point the camera at the whole scene</source>
        <translation>Die Kamera auf die ganze Szene richten</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="317"/>
        <source>Frame &amp;Selected</source>
        <translation>&amp;Auswahl einpassen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="318"/>
        <source>Point the camera at the selected object</source>
        <translation>Die Kamera auf das ausgewählte Objekt richten</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="322"/>
        <source>&amp;Front View</source>
        <translation>&amp;Vorderansicht</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="323"/>
        <source>Look along +Y, Z up</source>
        <translation>Entlang +Y blicken, Z oben</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="327"/>
        <source>&amp;Back View</source>
        <translation>&amp;Rückansicht</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="328"/>
        <source>Look along −Y, Z up</source>
        <translation>Entlang −Y blicken, Z oben</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="332"/>
        <source>&amp;Right View</source>
        <translation>Ansicht von r&amp;echts</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="333"/>
        <source>Look along −X, Z up</source>
        <translation>Entlang −X blicken, Z oben</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="337"/>
        <source>&amp;Left View</source>
        <translation>Ansicht von &amp;links</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="338"/>
        <source>Look along +X, Z up</source>
        <translation>Entlang +X blicken, Z oben</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="342"/>
        <source>&amp;Top View</source>
        <translation>Ansicht von &amp;oben</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="343"/>
        <source>Look down −Z, Y up</source>
        <translation>Entlang −Z nach unten blicken, Y oben</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="347"/>
        <source>Botto&amp;m View</source>
        <translation>Ansicht von &amp;unten</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="348"/>
        <source>Look up +Z</source>
        <translation>Entlang +Z nach oben blicken</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="353"/>
        <source>&amp;Orthographic</source>
        <translation>&amp;Orthografisch</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="354"/>
        <source>Parallel projection instead of perspective</source>
        <translation>Parallelprojektion statt Perspektive</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="359"/>
        <source>&amp;Wireframe</source>
        <translation>&amp;Drahtgitter</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="360"/>
        <source>Draw the objects as the edges of their triangles</source>
        <translation>Die Objekte als Kanten ihrer Dreiecke zeichnen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="365"/>
        <source>&amp;X-Ray</source>
        <translation>&amp;Röntgen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="366"/>
        <source>Draw the objects see-through</source>
        <translation>Die Objekte durchsichtig zeichnen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="371"/>
        <source>&amp;Play</source>
        <translation>&amp;Abspielen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="372"/>
        <source>Play or pause the animation</source>
        <translation>Die Animation abspielen oder anhalten</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="376"/>
        <source>Step &amp;Forward</source>
        <translation>Einen Schritt &amp;vor</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="377"/>
        <source>One frame later</source>
        <translation>Ein Frame später</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="381"/>
        <source>Step &amp;Backward</source>
        <translation>Einen Schritt &amp;zurück</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="382"/>
        <source>One frame earlier</source>
        <translation>Ein Frame früher</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="386"/>
        <source>Go to &amp;Start</source>
        <translation>Zum A&amp;nfang</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="387"/>
        <source>Go to the first frame</source>
        <translation>Zum ersten Frame gehen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="391"/>
        <source>Go to &amp;End</source>
        <translation>Zum &amp;Ende</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="392"/>
        <source>Go to the last frame</source>
        <translation>Zum letzten Frame gehen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="398"/>
        <source>&amp;Loop</source>
        <translation>&amp;Schleife</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="399"/>
        <source>Start again from the beginning at the end</source>
        <translation>Am Ende wieder von vorn beginnen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="402"/>
        <source>&amp;Add Keyframe</source>
        <translation>Schlüsselbild &amp;hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="403"/>
        <source>Key every selected object&apos;s pose at the current time</source>
        <translation>Die Pose jedes ausgewählten Objekts zur aktuellen Zeit als Keyframe setzen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="408"/>
        <source>Delete the selected keyframes</source>
        <translation>Die ausgewählten Keyframes löschen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="407"/>
        <source>&amp;Delete Keyframe</source>
        <translation>Schlüsselbild &amp;löschen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="414"/>
        <source>&amp;Constrain Keyframe</source>
        <translation>Schlüsselbild &amp;fixieren</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="415"/>
        <source>Keep the selected keyframe exactly when fitting, or free it</source>
        <translation>Das gewählte Schlüsselbild bei der Anpassung exakt halten oder freigeben</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="419"/>
        <source>&amp;Euler Filter</source>
        <translation>&amp;Euler-Filter</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="420"/>
        <source>Make the selected object&apos;s keys continuous: each key&apos;s quaternion in the hemisphere of the key before</source>
        <translation>Die Schlüsselbilder des gewählten Objekts stetig machen: das Quaternion jedes Schlüsselbilds in die Hemisphäre des vorigen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="423"/>
        <source>&amp;Next Flight Solution</source>
        <translation>&amp;Nächste Flugbahn</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="424"/>
        <source>Fly the current span of a ballistic track by its next free flight, by energy</source>
        <translation>Den aktuellen Abschnitt einer ballistischen Spur mit dem nächsten freien Flug fliegen, nach Energie geordnet</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="427"/>
        <source>P&amp;revious Flight Solution</source>
        <translation>&amp;Vorige Flugbahn</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="428"/>
        <source>Fly the current span of a ballistic track by its previous free flight, by energy</source>
        <translation>Den aktuellen Abschnitt einer ballistischen Spur mit dem vorigen freien Flug fliegen, nach Energie geordnet</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="431"/>
        <source>&amp;Copy</source>
        <translation>&amp;Kopieren</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="432"/>
        <source>Copy the selected keys, or with none selected the selected object&apos;s pose</source>
        <translation>Die ausgewählten Keys kopieren, oder ohne Auswahl die Pose des ausgewählten Objekts</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="436"/>
        <source>&amp;Paste</source>
        <translation>&amp;Einfügen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="437"/>
        <source>Paste copied keys or a pose at the current time on the selected objects</source>
        <translation>Kopierte Keys oder eine Pose zur aktuellen Zeit in die ausgewählten Objekte einfügen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="441"/>
        <source>Select &amp;All Keys</source>
        <translation>&amp;Alle Keys auswählen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="442"/>
        <source>Select every key of the selected object</source>
        <translation>Jeden Key des ausgewählten Objekts auswählen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="446"/>
        <source>Select &amp;No Keys</source>
        <translation>&amp;Keine Keys auswählen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="447"/>
        <source>Deselect every key</source>
        <translation>Die Auswahl aller Keys aufheben</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="451"/>
        <source>&amp;About Gyre</source>
        <translation>&amp;Über Gyre</translation>
    </message>
    <message>
        <location filename="../ui/main_window.ui" line="452"/>
        <source>Version, licence and the libraries Gyre is built on</source>
        <translation>Version, Lizenz und die Bibliotheken, auf denen Gyre aufbaut</translation>
    </message>
</context>
<context>
    <name>PreferencesDialog</name>
    <message>
        <location filename="../ui/preferences_dialog.ui" line="6"/>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <location filename="../ui/preferences_dialog.ui" line="12"/>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <location filename="../ui/preferences_dialog.ui" line="18"/>
        <source>The language of Gyre&apos;s menus, panels and messages</source>
        <translation>Die Sprache der Menüs, Bedienfelder und Meldungen von Gyre</translation>
    </message>
    <message>
        <location filename="../ui/preferences_dialog.ui" line="23"/>
        <source>The language changes when Gyre next starts.</source>
        <translation>Die Sprache wechselt beim nächsten Start von Gyre.</translation>
    </message>
</context>
<context>
    <name>ScrewBenderPanel</name>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="9"/>
        <source>Select an object to choose how its track is interpolated.</source>
        <translation>Wählen Sie ein Objekt, um zu bestimmen, wie seine Spur interpoliert wird.</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="41"/>
        <source>Interpolation</source>
        <translation>Interpolation</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="45"/>
        <source>&amp;Method</source>
        <translation>&amp;Verfahren</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="51"/>
        <source>How the track&apos;s orientation is interpolated between its keyframes</source>
        <translation>Wie die Orientierung der Spur zwischen ihren Schlüsselbildern interpoliert wird</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="59"/>
        <source>Subdivision</source>
        <translation>Unterteilung</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="63"/>
        <source>Used when the method is screw motion.</source>
        <translation>Wird verwendet, wenn das Verfahren Schraubbewegung ist.</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="69"/>
        <source>&amp;Scheme</source>
        <translation>&amp;Schema</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="75"/>
        <source>The Split&amp;Tweak rule that smooths the polyscrew at each level</source>
        <translation>Die Split&amp;Tweak-Regel, die die Polyschraube auf jeder Stufe glättet</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="80"/>
        <source>&amp;Levels</source>
        <translation>S&amp;tufen</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="86"/>
        <source>Each level doubles the poses</source>
        <translation>Jede Stufe verdoppelt die Posen</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="92"/>
        <source>Sequence</source>
        <translation>Folge</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="99"/>
        <source>C&amp;yclic</source>
        <translation>&amp;Zyklisch</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="100"/>
        <source>The last keyframe joins the first: a closed loop</source>
        <translation>Das letzte Schlüsselbild schließt an das erste an: eine geschlossene Schleife</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="105"/>
        <source>&amp;Open</source>
        <translation>&amp;Offen</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="106"/>
        <source>The motion starts at the first keyframe and ends at the last</source>
        <translation>Die Bewegung beginnt beim ersten Schlüsselbild und endet beim letzten</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="113"/>
        <source>&amp;Decoupled, for comparison</source>
        <translation>&amp;Entkoppelt, zum Vergleich</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="114"/>
        <source>The alternative the paper compares against: orientations by slerp, positions by the linear scheme, each subdivided on its own</source>
        <translation>Die Alternative, mit der der Artikel vergleicht: Orientierungen per Slerp, Positionen nach dem linearen Schema, jeweils für sich unterteilt</translation>
    </message>
    <message>
        <location filename="../ui/screwbender_panel.ui" line="119"/>
        <source>Poses</source>
        <translation>Posen</translation>
    </message>
</context>
<context>
    <name>gyre::FileError</name>
    <message>
        <location filename="../src/model/project_file.cpp" line="355"/>
        <source>these %1 keys bring the file past the %2 keys a project may hold</source>
        <translation>mit diesen %1 Schlüsseln hat die Datei mehr als die %2 Schlüssel, die ein Projekt haben darf</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="617"/>
        <source>these %1 times bring the file past the %2 times a project may hold</source>
        <translation>mit diesen %1 Zeiten hat die Datei mehr als die %2 Zeiten, die ein Projekt haben darf</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="358"/>
        <source>the file has no time lists</source>
        <translation>die Datei hat keine Zeitlisten</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="226"/>
        <source>is larger than 1 GiB, the most a project file may hold</source>
        <translation>ist größer als 1 GiB, das Höchstmaß für eine Projektdatei</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="362"/>
        <source>time list %1 holds %2 times for %3 keys</source>
        <translation>Zeitliste %1 enthält %2 Zeiten für %3 Schlüssel</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="591"/>
        <source>a version %1 file starts with &quot;%2&quot; and its version in binary, not with JSON text</source>
        <translation>eine Datei der Version %1 beginnt mit „%2“ und ihrer Version in Binärform, nicht mit JSON-Text</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="680"/>
        <source>the file ends inside its first %1 bytes</source>
        <translation>die Datei endet innerhalb ihrer ersten %1 Bytes</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="685"/>
        <source>a version %1 file is JSON text, not binary</source>
        <translation>eine Datei der Version %1 ist JSON-Text, nicht binär</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="689"/>
        <source>%1 bytes; a header may hold at most %2</source>
        <translation>%1 Bytes; ein Kopf darf höchstens %2 haben</translation>
    </message>
    <message>
        <location filename="../src/model/project_blocks.cpp" line="139"/>
        <source>%1 is neither 0 nor 1</source>
        <translation>%1 ist weder 0 noch 1</translation>
    </message>
    <message>
        <location filename="../src/model/project_blocks.cpp" line="273"/>
        <source>its block needs %1 bytes; the file has %2 left</source>
        <translation>sein Block braucht %1 Bytes; die Datei hat noch %2</translation>
    </message>
    <message>
        <location filename="../src/model/project_blocks.cpp" line="279"/>
        <source>the file ends %1 bytes into its block of %2</source>
        <translation>die Datei endet nach %1 Bytes seines Blocks von %2</translation>
    </message>
    <message>
        <location filename="../src/model/project_blocks.cpp" line="289"/>
        <source>the file goes on after its last block</source>
        <translation>die Datei geht nach ihrem letzten Block weiter</translation>
    </message>
    <message>
        <location filename="../src/model/project_blocks.cpp" line="295"/>
        <source>the writer has no block for it</source>
        <translation>der Schreiber hat keinen Block dafür</translation>
    </message>
    <message>
        <location filename="../src/model/project_blocks.cpp" line="298"/>
        <source>its block holds %1 bytes, not %2</source>
        <translation>sein Block hat %1 Bytes, nicht %2</translation>
    </message>
    <message>
        <location filename="../src/model/output_target.cpp" line="34"/>
        <source>cannot write to standard output: %1</source>
        <translation>in die Standardausgabe kann nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <location filename="../src/model/output_target.cpp" line="73"/>
        <location filename="../src/jobs/autosave.cpp" line="38"/>
        <source>cannot write: %1</source>
        <translation>kann nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <location filename="../src/jobs/autosave.cpp" line="83"/>
        <source>cannot create the autosave directory</source>
        <translation>das Verzeichnis für die automatische Sicherung kann nicht angelegt werden</translation>
    </message>
    <message>
        <location filename="../src/jobs/autosave.cpp" line="91"/>
        <source>cannot take the autosave lock</source>
        <translation>die Sperre der automatischen Sicherung kann nicht übernommen werden</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="168"/>
        <source>unknown value &quot;%1&quot;; expected one of %2</source>
        <translation>unbekannter Wert „%1“; erwartet wird einer von %2</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="263"/>
        <source>%1 bytes are not a whole number of %2-byte items</source>
        <translation>%1 Bytes sind keine ganze Zahl von %2-Byte-Einträgen</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="315"/>
        <source>a skin has 1 to %1 joints</source>
        <translation>ein Skin hat 1 bis %1 Gelenke</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="341"/>
        <location filename="../src/model/project_blocks.cpp" line="146"/>
        <source>the angles are not finite</source>
        <translation>die Winkel sind nicht endlich</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="392"/>
        <location filename="../src/model/value_checks.cpp" line="156"/>
        <source>a stroke needs at least one point</source>
        <translation>ein Strich braucht mindestens einen Punkt</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="394"/>
        <source>%1 times for %2 points; give none or one per point</source>
        <translation>%1 Zeiten für %2 Punkte; geben Sie keine oder eine je Punkt an</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="421"/>
        <source>these %1 control points bring the file past the %2 keys a project may hold</source>
        <translation>mit diesen %1 Kontrollpunkten hat die Datei mehr als die %2 Schlüssel, die ein Projekt haben darf</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="461"/>
        <location filename="../src/model/value_checks.cpp" line="207"/>
        <source>keys to restore without an applied fit</source>
        <translation>wiederherzustellende Schlüssel ohne angewendete Anpassung</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="472"/>
        <source>an object in Euler rotation mode interpolates euler or euler-cubic</source>
        <translation>ein Objekt im Euler-Rotationsmodus interpoliert mit euler oder euler-cubic</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="478"/>
        <source>an object in Euler rotation mode needs the angles of every key</source>
        <translation>ein Objekt im Euler-Rotationsmodus braucht die Winkel jedes Keys</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="479"/>
        <source>angles on an object in quaternion rotation mode</source>
        <translation>Winkel an einem Objekt im Quaternion-Rotationsmodus</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="481"/>
        <source>the angles do not give the key&apos;s orientation</source>
        <translation>die Winkel ergeben nicht die Orientierung des Keys</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="504"/>
        <source>the file has no meshes</source>
        <translation>die Datei hat keine Meshes</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="539"/>
        <source>%1 is also the id of objects[%2]</source>
        <translation>%1 ist auch die ID von objects[%2]</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="542"/>
        <location filename="../src/model/project_file.cpp" line="630"/>
        <source>no object has id %1</source>
        <translation>kein Objekt hat die ID %1</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="551"/>
        <source>object %1 is its own ancestor</source>
        <translation>Objekt %1 ist sein eigener Vorfahr</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="564"/>
        <source>object %1 comes after it in the file; parents come before their children</source>
        <translation>Objekt %1 steht in der Datei nach ihm; Eltern stehen vor ihren Kindern</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="585"/>
        <source>expected &quot;%1&quot;, found &quot;%2&quot;; this is not a Gyre project</source>
        <translation>erwartet „%1“, gefunden „%2“; dies ist kein Gyre-Projekt</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="765"/>
        <source>not saved, because its header (the objects&apos; names and settings, the sketches&apos; strokes) would hold %1 bytes, more than the %2 a project may hold</source>
        <translation>nicht gespeichert, weil ihr Kopf (die Namen und Einstellungen der Objekte, die Striche der Skizzen) %1 Bytes hätte, mehr als die %2, die ein Projekt haben darf</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="575"/>
        <source>the file has version %1, newer than this build of Gyre reads (%2 and older); open it with a newer Gyre</source>
        <translation>die Datei hat Version %1, neuer als diese Gyre-Version lesen kann (%2 und älter); öffnen Sie sie mit einem neueren Gyre</translation>
    </message>
    <message>
        <location filename="../src/model/output_target.cpp" line="42"/>
        <location filename="../src/model/project_file.cpp" line="740"/>
        <source>is a directory, not a file</source>
        <translation>ist ein Verzeichnis, keine Datei</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="743"/>
        <source>cannot open: %1</source>
        <translation>kann nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="647"/>
        <source>cannot read: %1</source>
        <translation>kann nicht gelesen werden: %1</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="660"/>
        <source>is empty; a project file holds a JSON object</source>
        <translation>ist leer; eine Projektdatei enthält ein JSON-Objekt</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="653"/>
        <source>not valid JSON: %1 at byte %2</source>
        <translation>kein gültiges JSON: %1 bei Byte %2</translation>
    </message>
    <message>
        <location filename="../src/model/project_file.cpp" line="758"/>
        <source>not saved, because the file would not read back: %1</source>
        <translation>nicht gespeichert, weil sich die Datei nicht wieder lesen ließe: %1</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="79"/>
        <source>object %1 &apos;%2&apos; is written as &apos;%3&apos; so that its name is unique</source>
        <translation>Objekt %1 „%2“ wird als „%3“ geschrieben, damit sein Name eindeutig ist</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="481"/>
        <source>cannot be written as FBX: %1</source>
        <translation>kann nicht als FBX geschrieben werden: %1</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="195"/>
        <source>baking at %1 fps gives more than %2 samples</source>
        <translation>Backen mit %1 fps ergibt mehr als %2 Abtastwerte</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="202"/>
        <source>the motion of &apos;%1&apos; cannot be baked: %2</source>
        <translation>die Bewegung von „%1“ kann nicht gebacken werden: %2</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="174"/>
        <source>the motion of &apos;%1&apos; cannot be evaluated: %2</source>
        <translation>die Bewegung von „%1“ kann nicht ausgewertet werden: %2</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="141"/>
        <source>object %1 names parent %2, which does not come before it; it is written at the top level</source>
        <translation>Objekt %1 nennt das Elternobjekt %2, das nicht vor ihm steht; es wird auf oberster Ebene geschrieben</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="157"/>
        <source>the skin of &apos;%1&apos; names object %2, which the scene does not hold; its mesh is written rigid</source>
        <translation>die Haut von &apos;%1&apos; nennt Objekt %2, das die Szene nicht enthält; ihr Mesh wird starr geschrieben</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="184"/>
        <source>the mesh of &apos;%1&apos; has an index past its vertices</source>
        <translation>das Mesh von „%1“ hat einen Index jenseits seiner Eckpunkte</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="411"/>
        <source>Assimp cannot write it</source>
        <translation>Assimp kann sie nicht schreiben</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="412"/>
        <source>Assimp cannot write it: %1</source>
        <translation>Assimp kann sie nicht schreiben: %1</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="418"/>
        <source>Assimp wrote nothing</source>
        <translation>Assimp hat nichts geschrieben</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="437"/>
        <source>cannot be written as glTF: %1</source>
        <translation>kann nicht als glTF geschrieben werden: %1</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="461"/>
        <source>the frame rate must be a finite number above zero</source>
        <translation>die Bildrate muss eine endliche Zahl über null sein</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="463"/>
        <source>the scene&apos;s time range is empty or not finite</source>
        <translation>der Zeitbereich der Szene ist leer oder nicht endlich</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="466"/>
        <source>the scene has no meshes, and OBJ holds nothing else</source>
        <translation>die Szene hat keine Meshes, und OBJ enthält nichts anderes</translation>
    </message>
    <message>
        <location filename="../src/io/scene_export.cpp" line="468"/>
        <source>OBJ holds no motion: the meshes are written as posed at the start time</source>
        <translation>OBJ enthält keine Bewegung: die Meshes werden so geschrieben, wie sie zur Startzeit stehen</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="58"/>
        <source>no such file</source>
        <translation>Datei nicht vorhanden</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="60"/>
        <source>is a directory, not a scene file</source>
        <translation>ist ein Verzeichnis, keine Szenendatei</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="62"/>
        <source>cannot be read (permission denied)</source>
        <translation>kann nicht gelesen werden (keine Berechtigung)</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="64"/>
        <source>the file is empty</source>
        <translation>die Datei ist leer</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="77"/>
        <source>the file holds no meshes and no animation</source>
        <translation>die Datei enthält weder Meshes noch Animation</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="86"/>
        <source>not a scene Gyre can read: %1</source>
        <translation>keine Szene, die Gyre lesen kann: %1</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="90"/>
        <source>the file holds no scene nodes</source>
        <translation>die Datei enthält keine Szenenknoten</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="132"/>
        <source>%1 key %2 is not finite</source>
        <translation>%1schlüssel %2 ist nicht endlich</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="135"/>
        <source>%1 key %2 is not a rotation (a zero quaternion)</source>
        <translation>%1schlüssel %2 ist keine Rotation (ein Null-Quaternion)</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="138"/>
        <source>%1 key %2 is not after the key before it</source>
        <translation>%1schlüssel %2 liegt nicht nach dem Schlüssel davor</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="147"/>
        <source>node &apos;%1&apos;: %2</source>
        <translation>Knoten „%1“: %2</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="395"/>
        <source>node &apos;%1&apos; has more than one channel in animation &apos;%2&apos;; the first is used</source>
        <translation>Knoten „%1“ hat mehr als einen Kanal in der Animation „%2“; der erste wird verwendet</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="401"/>
        <source>node &apos;%1&apos; is moved by more than one of the chosen animations; the later one, &apos;%2&apos;, is used</source>
        <translation>Knoten „%1“ wird von mehr als einer der gewählten Animationen bewegt; die spätere, „%2“, wird verwendet</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="505"/>
        <source>animation &apos;%1&apos; moves &apos;%2&apos;, which is not in the scene</source>
        <translation>Animation „%1“ bewegt den Knoten „%2“, den es in der Szene nicht gibt</translation>
    </message>
    <message numerus="yes">
        <location filename="../src/io/scene_import.cpp" line="536"/>
        <source>the file has %n animation(s); there is no animation %1</source>
        <translation>
            <numerusform>die Datei hat %n Animation; es gibt keine Animation %1</numerusform>
            <numerusform>die Datei hat %n Animationen; es gibt keine Animation %1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="560"/>
        <source>the frame rate %1 is not in (0, %2]</source>
        <translation>die Bildrate %1 liegt nicht in (0, %2]</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="567"/>
        <source>the unit %1 m is not a positive length</source>
        <translation>die Einheit %1 m ist keine positive Länge</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="671"/>
        <source>Assimp reads %1 animations and TinyGLTF %2</source>
        <translation>Assimp liest %1 Animationen und TinyGLTF %2</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="451"/>
        <source>node &apos;%1&apos; has a non-uniform scale; its children get the mean scale</source>
        <translation>Knoten „%1“ hat eine ungleichmäßige Skalierung; seine Kinder erhalten die mittlere Skalierung</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="258"/>
        <source>mesh &apos;%1&apos;: %2</source>
        <translation>Mesh „%1“: %2</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="469"/>
        <source>rotation</source>
        <translation>Rotations</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="472"/>
        <source>position</source>
        <translation>Positions</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="487"/>
        <source>scaling</source>
        <translation>Skalierungs</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="493"/>
        <source>node &apos;%1&apos;: its scale changes over time; Gyre&apos;s motion is rigid, so the scale of its first key is kept</source>
        <translation>Knoten „%1“: seine Skalierung ändert sich mit der Zeit; Gyres Bewegung ist starr, daher wird die Skalierung seines ersten Animationsschlüssels beibehalten</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="549"/>
        <source>mesh and morph animation is not imported; only node motion is</source>
        <translation>Mesh- und Morph-Animation wird nicht importiert, nur die Bewegung der Knoten</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import.cpp" line="551"/>
        <source>cameras and lights are not imported</source>
        <translation>Kameras und Lichter werden nicht importiert</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="24"/>
        <source>a boolean</source>
        <translation>ein Wahrheitswert</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="26"/>
        <location filename="../src/model/json_field.cpp" line="48"/>
        <source>a number</source>
        <translation>eine Zahl</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="29"/>
        <source>the string &quot;%1&quot;</source>
        <translation>die Zeichenkette „%1“</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="33"/>
        <location filename="../src/model/json_field.cpp" line="52"/>
        <source>an array</source>
        <translation>ein Array</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="35"/>
        <location filename="../src/model/json_field.cpp" line="54"/>
        <source>an object</source>
        <translation>ein Objekt</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="39"/>
        <source>nothing</source>
        <translation>nichts</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="46"/>
        <source>true or false</source>
        <translation>true oder false</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="50"/>
        <source>a string</source>
        <translation>eine Zeichenkette</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="70"/>
        <source>the top level</source>
        <translation>die oberste Ebene</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="77"/>
        <source>expected %1, found %2</source>
        <translation>erwartet: %1, gefunden: %2</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="88"/>
        <source>missing</source>
        <translation>fehlt</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="116"/>
        <location filename="../src/model/value_checks.cpp" line="66"/>
        <source>%1 is not a finite number</source>
        <translation>%1 ist keine endliche Zahl</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="124"/>
        <source>%1 is not a whole number</source>
        <translation>%1 ist keine ganze Zahl</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="126"/>
        <source>%1 is outside %2 to %3</source>
        <translation>%1 liegt außerhalb von %2 bis %3</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="146"/>
        <source>not valid base64</source>
        <translation>kein gültiges Base64</translation>
    </message>
    <message>
        <location filename="../src/model/json_field.cpp" line="155"/>
        <source>expected %1 numbers, found %2</source>
        <translation>erwartet: %1 Zahlen, gefunden: %2</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="30"/>
        <source>not all components are finite</source>
        <translation>nicht alle Komponenten sind endlich</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="40"/>
        <source>the %1 is zero</source>
        <translation>%1 ist null</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="42"/>
        <source>the %1 has length %2; it must have length 1</source>
        <translation>%1 hat die Länge %2; die Länge muss 1 sein</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="73"/>
        <source>%1 is negative</source>
        <translation>%1 ist negativ</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="80"/>
        <source>%1 is not positive</source>
        <translation>%1 ist nicht positiv</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="86"/>
        <source>direction</source>
        <translation>die Richtung</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="90"/>
        <source>quaternion</source>
        <translation>das Quaternion</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="101"/>
        <source>position coordinate %1 is beyond ±%2</source>
        <translation>die Positionskoordinate %1 liegt außerhalb von ±%2</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="109"/>
        <source>time %1 is beyond ±%2 s</source>
        <translation>die Zeit %1 liegt außerhalb von ±%2 s</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="116"/>
        <source>time %1 does not come after the time before it, %2</source>
        <translation>die Zeit %1 liegt nicht nach der Zeit davor, %2</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="125"/>
        <source>the value has length %1; a fitted value needs length at least %2</source>
        <translation>der Wert hat die Länge %1; ein angepasster Wert braucht mindestens die Länge %2</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="134"/>
        <source>the derivative has length %1 per second; the most it may have is %2</source>
        <translation>die Ableitung hat die Länge %1 pro Sekunde; höchstens zulässig ist %2</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="160"/>
        <source>a stroke has no times or one per point</source>
        <translation>ein Strich hat keine Zeiten oder eine je Punkt</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="176"/>
        <source>the pattern&apos;s repeat count %1 is negative</source>
        <translation>die Wiederholungszahl %1 des Musters ist negativ</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="213"/>
        <source>subdivision levels %1 are outside 0 to %2</source>
        <translation>die Unterteilungsstufen %1 liegen außerhalb von 0 bis %2</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="219"/>
        <source>%1 keys on a ballistic track, which solves a free flight for each span; it may hold %2</source>
        <translation>%1 Keys auf einer ballistischen Spur, die für jeden Abschnitt einen freien Flug löst; sie darf %2 enthalten</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="227"/>
        <source>%1 keys at %2 levels make %3 poses; the budget is %4</source>
        <translation>%1 Schlüssel ergeben bei %2 Stufen %3 Posen; erlaubt sind höchstens %4</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="244"/>
        <source>a frame rate of %1 is above %2</source>
        <translation>eine Bildrate von %1 liegt über %2</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="252"/>
        <source>the end time %1 does not come after the start time %2</source>
        <translation>die Endzeit %1 liegt nicht nach der Startzeit %2</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="257"/>
        <source>%1 s at %2 fps make %3 frames; the budget is %4</source>
        <translation>%1 s bei %2 fps ergeben %3 Frames; erlaubt sind höchstens %4</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="266"/>
        <source>a mesh position is not finite</source>
        <translation>eine Mesh-Position ist nicht endlich</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="269"/>
        <source>a mesh normal is not finite</source>
        <translation>eine Mesh-Normale ist nicht endlich</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="271"/>
        <source>the mesh has %1 normals for %2 positions</source>
        <translation>das Mesh hat %1 Normalen für %2 Positionen</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="273"/>
        <source>the mesh&apos;s %1 indices do not make whole triangles</source>
        <translation>die %1 Indizes des Meshes ergeben keine ganzen Dreiecke</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="276"/>
        <source>mesh index %1 is beyond its %2 positions</source>
        <translation>der Mesh-Index %1 liegt jenseits seiner %2 Positionen</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="285"/>
        <source>the skin has %1 joints, more than the %2 a mesh may follow</source>
        <translation>der Skin hat %1 Gelenke, mehr als die %2, denen ein Mesh folgen kann</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="288"/>
        <source>skin joint %1 is 0 or named twice</source>
        <translation>Skin-Gelenk %1 ist 0 oder doppelt genannt</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="290"/>
        <source>the skin has %1 inverse bind matrices for %2 joints</source>
        <translation>der Skin hat %1 inverse Bindematrizen für %2 Gelenke</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="294"/>
        <source>the inverse bind matrix of skin joint %1 is not a finite affine transform</source>
        <translation>die inverse Bindematrix von Skin-Gelenk %1 ist keine endliche affine Transformation</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="297"/>
        <source>the skin has %1 joint sets and %2 weight sets for %3 positions</source>
        <translation>der Skin hat %1 Gelenksätze und %2 Gewichtssätze für %3 Positionen</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="304"/>
        <source>skin vertex %1 names joint %2 of %3</source>
        <translation>Skin-Eckpunkt %1 nennt Gelenk %2 von %3</translation>
    </message>
    <message>
        <location filename="../src/model/value_checks.cpp" line="307"/>
        <source>the weights of skin vertex %1 are not finite, ≥ 0 and at most 1 in sum</source>
        <translation>die Gewichte von Skin-Eckpunkt %1 sind nicht endlich, ≥ 0 und in der Summe höchstens 1</translation>
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
        <translation>das Szenen-Leseprogramm %1 ist nicht neben %2 installiert</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="158"/>
        <source>the scene reader %1 is missing or not executable</source>
        <translation>das Szenen-Leseprogramm %1 fehlt oder ist nicht ausführbar</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="174"/>
        <source>the scene reader %1 cannot be started: %2</source>
        <translation>das Szenen-Leseprogramm %1 lässt sich nicht starten: %2</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="119"/>
        <source>the scene reader took longer than %1 s and was stopped; the file may be damaged or too large</source>
        <translation>das Szenen-Leseprogramm brauchte länger als %1 s und wurde angehalten; die Datei ist vielleicht beschädigt oder zu groß</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="123"/>
        <source>the scene reader&apos;s reply is larger than %1</source>
        <translation>die Antwort des Szenen-Leseprogramms ist größer als %1</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="133"/>
        <source>the scene reader crashed on this file (signal %1, %2)%3</source>
        <translation>das Szenen-Leseprogramm ist an dieser Datei abgestürzt (Signal %1, %2)%3</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="191"/>
        <source>the scene reader needed more than %1 of memory for this file and was stopped</source>
        <translation>das Szenen-Leseprogramm brauchte für diese Datei mehr als %1 Speicher und wurde angehalten</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="137"/>
        <source>the scene reader failed (exit status %1)%2</source>
        <translation>das Szenen-Leseprogramm ist gescheitert (Exit-Status %1)%2</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="102"/>
        <source>the scene reader&apos;s reply is malformed: %1</source>
        <translation>die Antwort des Szenen-Leseprogramms ist fehlerhaft: %1</translation>
    </message>
    <message>
        <location filename="../src/io/scene_worker.cpp" line="106"/>
        <source>the scene reader&apos;s reply is malformed: the wrong kind of reply</source>
        <translation>die Antwort des Szenen-Leseprogramms ist fehlerhaft: eine Antwort der falschen Art</translation>
    </message>
    <message>
        <location filename="../src/io/baked_scene.cpp" line="171"/>
        <source>glTF times cannot be negative: the motion is written %1 s later, from 0 s</source>
        <translation>glTF-Zeiten können nicht negativ sein: die Bewegung wird %1 s später geschrieben, ab 0 s</translation>
    </message>
    <message>
        <location filename="../src/io/baked_scene.cpp" line="190"/>
        <source>&apos;%1&apos;: two of its keys are within a float32 step; its rotation and translation are written as baked samples, not as its splines</source>
        <translation>„%1“: zwei seiner Schlüssel liegen innerhalb eines float32-Schritts; seine Rotation und Translation werden als gebackene Abtastwerte geschrieben, nicht als seine Splines</translation>
    </message>
    <message>
        <location filename="../src/io/baked_scene.cpp" line="197"/>
        <source>&apos;%1&apos;: %2 baked samples are left out, each within a float32 step of the one kept (glTF stores times as float32)</source>
        <translation>„%1“: %2 gebackene Abtastwerte werden ausgelassen, jeder innerhalb eines float32-Schritts vom beibehaltenen (glTF speichert Zeiten als float32)</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="29"/>
        <source>%1 is %2 bytes, over the %3 bytes a glTF buffer may have</source>
        <translation>%1 hat %2 Bytes, mehr als die %3 Bytes, die ein glTF-Buffer haben darf</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="63"/>
        <source>there is no accessor %1</source>
        <translation>es gibt keinen Accessor %1</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="67"/>
        <source>count %1 is over the %2 elements Gyre reads</source>
        <translation>die Anzahl %1 ist größer als die %2 Elemente, die Gyre liest</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="75"/>
        <source>there is no buffer view %1</source>
        <translation>es gibt keine Buffer-View %1</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="78"/>
        <source>its buffer view names no buffer</source>
        <translation>seine Buffer-View nennt keinen Buffer</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="84"/>
        <source>%1 elements from byte %2 run past its buffer view&apos;s %3 bytes</source>
        <translation>%1 Elemente ab Byte %2 reichen über die %3 Bytes seiner Buffer-View hinaus</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="89"/>
        <source>its buffer view runs past the buffer&apos;s %1 bytes</source>
        <translation>seine Buffer-View reicht über die %1 Bytes des Buffers hinaus</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="102"/>
        <source>there is no such sampler</source>
        <translation>einen solchen Sampler gibt es nicht</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="113"/>
        <source>&apos;%1&apos; is not an interpolation</source>
        <translation>„%1“ ist keine Interpolation</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="122"/>
        <source>%1 times need %2 output elements; the output has %3</source>
        <translation>%1 Zeiten brauchen %2 Ausgabeelemente; die Ausgabe hat %3</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="130"/>
        <source>time %1 is not finite or not after the one before it</source>
        <translation>Zeit %1 ist nicht endlich oder liegt nicht nach der vorherigen</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="138"/>
        <source>element %1 is not finite</source>
        <translation>Element %1 ist nicht endlich</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="149"/>
        <source>rotation %1 is a zero quaternion</source>
        <translation>Rotation %1 ist ein Null-Quaternion</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="220"/>
        <source>not a glTF file Gyre can read: %1</source>
        <translation>keine glTF-Datei, die Gyre lesen kann: %1</translation>
    </message>
    <message>
        <location filename="../src/io/gltf_animation.cpp" line="337"/>
        <source>node &apos;%1&apos;: its motion at %2 fps needs more than %3 keys</source>
        <translation>Knoten „%1“: seine Bewegung braucht bei %2 fps mehr als %3 Schlüssel</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="164"/>
        <source>the FBX time mode</source>
        <translation>der FBX-Zeitmodus</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="171"/>
        <source>the BVH frame time</source>
        <translation>die Frame Time der BVH-Datei</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="176"/>
        <source>every key is on a frame of %1 fps</source>
        <translation>jeder Schlüssel liegt auf einem Frame von %1 fps</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="180"/>
        <source>no animation; Gyre&apos;s default</source>
        <translation>keine Animation; Gyres Standardwert</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="181"/>
        <source>the keys are on the frames of no common rate; Gyre&apos;s default</source>
        <translation>die Schlüssel liegen auf den Frames keiner gemeinsamen Rate; Gyres Standardwert</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="188"/>
        <source>written by Assimp, whose FBX unit says nothing; metres assumed</source>
        <translation>von Assimp geschrieben, dessen FBX-Einheit nichts aussagt; Meter angenommen</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="195"/>
        <source>the FBX UnitScaleFactor, %1 cm</source>
        <translation>der FBX-UnitScaleFactor, %1 cm</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="198"/>
        <source>FBX&apos;s default, 1 cm</source>
        <translation>der FBX-Standardwert, 1 cm</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="205"/>
        <source>the Collada &lt;unit&gt;</source>
        <translation>das Collada-Element &lt;unit&gt;</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="208"/>
        <source>Collada&apos;s default, 1 m</source>
        <translation>der Collada-Standardwert, 1 m</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="211"/>
        <source>glTF is in metres</source>
        <translation>glTF rechnet in Metern</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="212"/>
        <source>the format has no unit; metres assumed</source>
        <translation>das Format hat keine Einheit; Meter angenommen</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="229"/>
        <source>the file says its up axis is %1; Gyre converts Y-up and Z-up scenes only, so it is read as Y-up</source>
        <translation>laut der Datei ist ihre Hochachse %1; Gyre wandelt nur Szenen mit Y oben oder Z oben um, daher wird sie mit Y oben gelesen</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="237"/>
        <source>the FBX UpAxis</source>
        <translation>die FBX-Angabe UpAxis</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="246"/>
        <source>the Collada &lt;up_axis&gt;</source>
        <translation>das Collada-Element &lt;up_axis&gt;</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="250"/>
        <source>Collada&apos;s default, Y</source>
        <translation>der Collada-Standardwert, Y</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="255"/>
        <source>glTF is Y-up</source>
        <translation>glTF hat Y oben</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_settings.cpp" line="255"/>
        <source>Y-up assumed</source>
        <translation>Y oben angenommen</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_takes.cpp" line="90"/>
        <source>&apos;%1&apos; plays take %2 &apos;%3&apos;</source>
        <translation>„%1“ spielt Take %2 „%3“</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_takes.cpp" line="92"/>
        <source>the file&apos;s %1 takes are Blender&apos;s, one for every object and action; each object gets its own action: %2</source>
        <translation>die %1 Takes der Datei stammen von Blender, einer für jedes Objekt und jede Aktion; jedes Objekt erhält seine eigene Aktion: %2</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_skin.cpp" line="42"/>
        <source>mesh &apos;%1&apos;, bone &apos;%2&apos;: %3</source>
        <translation>Mesh „%1“, Knochen „%2“: %3</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_skin.cpp" line="47"/>
        <source>its offset matrix is not finite</source>
        <translation>seine Offset-Matrix ist nicht endlich</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_skin.cpp" line="51"/>
        <source>weight %1 names vertex %2 of %3</source>
        <translation>Gewicht %1 nennt Eckpunkt %2 von %3</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_skin.cpp" line="53"/>
        <source>weight %1 is not a finite number ≥ 0</source>
        <translation>Gewicht %1 ist keine endliche Zahl ≥ 0</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_skin.cpp" line="63"/>
        <source>mesh &apos;%1&apos; has %2 bones, more than the %3 Gyre can skin; it shows in its bind pose</source>
        <translation>Mesh „%1“ hat %2 Knochen, mehr als die %3, die Gyre skinnen kann; es wird in seiner Bindepose gezeigt</translation>
    </message>
    <message>
        <location filename="../src/io/scene_import_skin.cpp" line="74"/>
        <source>mesh &apos;%1&apos;: its bone &apos;%2&apos; is not a node of the scene; it shows in its bind pose</source>
        <translation>Mesh „%1“: sein Knochen „%2“ ist kein Knoten der Szene; es wird in seiner Bindepose gezeigt</translation>
    </message>
    <message>
        <location filename="../src/model/key_clipboard.cpp" line="40"/>
        <source>the text is not keys copied from Gyre</source>
        <translation>der Text sind keine aus Gyre kopierten Keys</translation>
    </message>
    <message>
        <location filename="../src/model/key_clipboard.cpp" line="42"/>
        <source>%1 bytes of text are more than the %2 that keys may take</source>
        <translation>%1 Bytes Text sind mehr als die %2, die Keys einnehmen dürfen</translation>
    </message>
    <message>
        <location filename="../src/model/key_clipboard.cpp" line="69"/>
        <source>no keys were copied</source>
        <translation>es wurden keine Keys kopiert</translation>
    </message>
    <message>
        <location filename="../src/model/key_clipboard.cpp" line="71"/>
        <source>%1 keys are more than the %2 a project may hold</source>
        <translation>%1 Keys sind mehr als die %2, die ein Projekt enthalten darf</translation>
    </message>
    <message>
        <location filename="../src/model/key_clipboard.cpp" line="73"/>
        <source>a pose is one object&apos;s one key</source>
        <translation>eine Pose ist ein Key eines Objekts</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="52"/>
        <source>the inertia has a value that is not a finite number</source>
        <translation>der Trägheitstensor hat einen Wert, der keine endliche Zahl ist</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="54"/>
        <source>the inertia tensor is not symmetric</source>
        <translation>der Trägheitstensor ist nicht symmetrisch</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="56"/>
        <source>the inertia tensor is not positive definite: every principal moment must be above 0</source>
        <translation>der Trägheitstensor ist nicht positiv definit: jedes Hauptträgheitsmoment muss über 0 liegen</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="58"/>
        <source>no body has this inertia: its two smaller principal moments add up to less than the largest</source>
        <translation>kein Körper hat diese Trägheit: seine zwei kleineren Hauptträgheitsmomente ergeben zusammen weniger als das größte</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="80"/>
        <source>as typed</source>
        <translation>wie eingegeben</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="82"/>
        <source>from the mesh, solid</source>
        <translation>aus dem Mesh, massiv</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="84"/>
        <source>from the mesh, as a thin shell: the mesh is not closed</source>
        <translation>aus dem Mesh, als dünne Schale: das Mesh ist nicht geschlossen</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="86"/>
        <source>from the mesh&apos;s bounding box: the mesh has no area</source>
        <translation>aus dem Begrenzungsquader des Meshs: das Mesh hat keine Fläche</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="94"/>
        <source>the mass must be a number above 0</source>
        <translation>die Masse muss eine Zahl über 0 sein</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="96"/>
        <source>the centre of mass is not a finite point</source>
        <translation>der Schwerpunkt ist kein endlicher Punkt</translation>
    </message>
    <message>
        <location filename="../src/model/object_mass.cpp" line="116"/>
        <source>the inertia needs six numbers: Ixx, Iyy, Izz, Ixy, Ixz, Iyz</source>
        <translation>der Trägheitstensor braucht sechs Zahlen: Ixx, Iyy, Izz, Ixy, Ixz, Iyz</translation>
    </message>
    <message>
        <location filename="../src/model/flight_choices.cpp" line="25"/>
        <source>%1 flight choices for %2 spans between the keys: one a span at most</source>
        <translation>%1 Flugwahlen für %2 Abschnitte zwischen den Keys: höchstens eine je Abschnitt</translation>
    </message>
    <message>
        <location filename="../src/model/project_json.cpp" line="74"/>
        <source>&apos;%1&apos; is neither quaternion nor euler</source>
        <translation>&apos;%1&apos; ist weder quaternion noch euler</translation>
    </message>
    <message>
        <location filename="../src/model/project_json.cpp" line="79"/>
        <source>&apos;%1&apos; is neither intrinsic nor extrinsic</source>
        <translation>&apos;%1&apos; ist weder intrinsic noch extrinsic</translation>
    </message>
    <message>
        <location filename="../src/model/project_json.cpp" line="84"/>
        <source>&apos;%1&apos; is not an order of three axes</source>
        <translation>&apos;%1&apos; ist keine Reihenfolge dreier Achsen</translation>
    </message>
</context>
<context>
    <name>gyre::app::AddObjectActions</name>
    <message>
        <location filename="../src/app/add_object_actions.cpp" line="41"/>
        <location filename="../src/app/add_object_actions.cpp" line="57"/>
        <source>Empty</source>
        <translation>Empty</translation>
    </message>
    <message>
        <location filename="../src/app/add_object_actions.cpp" line="65"/>
        <source>Add %1</source>
        <translation>%1 hinzufügen</translation>
    </message>
</context>
<context>
    <name>gyre::app::ChannelListModel</name>
    <message>
        <location filename="../src/app/graph_editor/channel_list_model.cpp" line="60"/>
        <source>Euler %1 (°)</source>
        <translation>Euler %1 (°)</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/channel_list_model.cpp" line="62"/>
        <source>quaternion w</source>
        <translation>Quaternion w</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/channel_list_model.cpp" line="66"/>
        <source>quaternion %1</source>
        <translation>Quaternion %1</translation>
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
        <translation>Position %1</translation>
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
        <translation>Rotationsenergie (J)</translation>
    </message>
</context>
<context>
    <name>gyre::app::DrawnMotion</name>
    <message>
        <location filename="../src/app/viewport/drawn_motion.cpp" line="16"/>
        <source>The motion could not be rebuilt: %1</source>
        <translation>Die Bewegung konnte nicht neu aufgebaut werden: %1</translation>
    </message>
    <message>
        <location filename="../src/app/viewport/drawn_motion.cpp" line="26"/>
        <location filename="../src/app/viewport/drawn_motion.cpp" line="43"/>
        <source>The trail could not be built: %1</source>
        <translation>Die Stroboskopspur konnte nicht aufgebaut werden: %1</translation>
    </message>
</context>
<context>
    <name>gyre::app::FitController</name>
    <message>
        <location filename="../src/app/sketch/fit_controller.cpp" line="21"/>
        <source>Against what was drawn: %1 rad²/s before, %2 after.</source>
        <translation>Gegenüber dem Gezeichneten: vorher %1 rad²/s, nachher %2.</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_controller.cpp" line="27"/>
        <source>Fit applied: the motion now follows the sketch within δ = %1 (largest relative error %2, %3 rounds, %4 s).</source>
        <translation>Anpassung angewendet: Die Bewegung folgt der Skizze jetzt innerhalb von δ = %1 (größter relativer Fehler %2, %3 Runden, %4 s).</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_controller.cpp" line="34"/>
        <source>Fit stopped at its limit of added control points, still off the sketch by a relative error of up to %1 (δ = %2); its last result was applied.</source>
        <translation>Die Anpassung hat an ihrer Grenze für hinzugefügte Kontrollpunkte angehalten und weicht noch mit einem relativen Fehler von bis zu %1 von der Skizze ab (δ = %2); ihr letztes Ergebnis wurde angewendet.</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_controller.cpp" line="39"/>
        <source>Fit could not meet δ = %1: where it is furthest off (relative error %2) it has no room for another control point, often because constrained keys there disagree with the sketch; its result was applied.</source>
        <translation>Die Anpassung konnte δ = %1 nicht einhalten: Wo sie am weitesten abweicht (relativer Fehler %2), hat sie keinen Platz für einen weiteren Kontrollpunkt, oft weil fixierte Schlüsselbilder dort der Skizze widersprechen; ihr Ergebnis wurde angewendet.</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_controller.cpp" line="48"/>
        <source>Fit stopped after %1 rounds, still off the sketch by a relative error of up to %2 (δ = %3); its last result was applied.</source>
        <translation>Die Anpassung hat nach %1 Runden angehalten und weicht noch mit einem relativen Fehler von bis zu %2 von der Skizze ab (δ = %3); ihr letztes Ergebnis wurde angewendet.</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_controller.cpp" line="67"/>
        <source>Fit failed, nothing was applied: %1</source>
        <translation>Anpassung fehlgeschlagen, nichts wurde angewendet: %1</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_controller.cpp" line="69"/>
        <source>Fit cancelled; nothing was applied.</source>
        <translation>Anpassung abgebrochen; nichts wurde angewendet.</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_controller.cpp" line="139"/>
        <source>Fit not applied: the track changed while it ran.</source>
        <translation>Anpassung nicht angewendet: Die Spur hat sich während der Anpassung geändert.</translation>
    </message>
</context>
<context>
    <name>gyre::app::FitPanel</name>
    <message>
        <location filename="../src/app/sketch/fit_panel.cpp" line="71"/>
        <source>Fitting…</source>
        <translation>Anpassung läuft…</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_panel.cpp" line="276"/>
        <source>Not changed: %1.</source>
        <translation>Nicht geändert: %1.</translation>
    </message>
</context>
<context>
    <name>gyre::app::FitProgress</name>
    <message>
        <location filename="../src/app/sketch/fit_progress.cpp" line="20"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_progress.cpp" line="26"/>
        <source>Stop the fit; the motion stays as it is</source>
        <translation>Die Anpassung anhalten; die Bewegung bleibt, wie sie ist</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_progress.cpp" line="43"/>
        <source>Fitting…</source>
        <translation>Anpassung läuft…</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_progress.cpp" line="53"/>
        <source>Fit: round %v of %m, largest relative error %1</source>
        <translation>Anpassung: Runde %v von %m, größter relativer Fehler %1</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/fit_progress.cpp" line="54"/>
        <source>Fit: round %v of %m</source>
        <translation>Anpassung: Runde %v von %m</translation>
    </message>
</context>
<context>
    <name>gyre::app::GraphEditorPanel</name>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="103"/>
        <source>The channels to plot: check one to show its curve</source>
        <translation>Die darzustellenden Kanäle: einen ankreuzen, um seine Kurve zu zeigen</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="145"/>
        <source>The order of the Euler angles, as the inspector shows them</source>
        <translation>Die Reihenfolge der Eulerwinkel, wie der Inspektor sie zeigt</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="146"/>
        <source>Euler &amp;order:</source>
        <translation>Euler-&amp;Reihenfolge:</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="150"/>
        <source>world frame</source>
        <translation>Weltsystem</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="151"/>
        <source>object&apos;s frame</source>
        <translation>Objektsystem</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="152"/>
        <source>The frame the angular velocity&apos;s and angular momentum&apos;s components are given in</source>
        <translation>Das Bezugssystem der Komponenten von Winkelgeschwindigkeit und Drehimpuls</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="153"/>
        <source>ω &amp;in:</source>
        <translation>ω &amp;im:</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="158"/>
        <source>Frame &amp;All</source>
        <translation>&amp;Alles zeigen</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="159"/>
        <source>Show the whole time range and every shown curve (Home)</source>
        <translation>Den ganzen Zeitbereich und jede gezeigte Kurve zeigen (Pos1)</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="160"/>
        <source>Frame &amp;Selected</source>
        <translation>Auswahl &amp;zeigen</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="162"/>
        <source>Show the selected key between its neighbours</source>
        <translation>Das gewählte Schlüsselbild zwischen seinen Nachbarn zeigen</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="170"/>
        <source>&amp;Move Keys</source>
        <translation>Keys &amp;verschieben</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="172"/>
        <source>Move the selected keys with the pointer; click to keep, Esc to cancel</source>
        <translation>Die ausgewählten Keys mit dem Zeiger verschieben; Klick behält, Esc bricht ab</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="173"/>
        <source>&amp;Scale Keys</source>
        <translation>Keys &amp;skalieren</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="175"/>
        <source>Scale the selected keys&apos; times about the current frame; click to keep, Esc to cancel</source>
        <translation>Die Zeiten der ausgewählten Keys um das aktuelle Frame skalieren; Klick behält, Esc bricht ab</translation>
    </message>
    <message>
        <location filename="../src/app/graph_editor/graph_editor_panel.cpp" line="225"/>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
</context>
<context>
    <name>gyre::app::ImportDialog</name>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="29"/>
        <source>The file has no animation.</source>
        <translation>Die Datei hat keine Animation.</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="31"/>
        <source>The file has one animation.</source>
        <translation>Die Datei hat eine Animation.</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="33"/>
        <source>Each animation moves nodes no other moves, so all are imported together.</source>
        <translation>Jede Animation bewegt Knoten, die keine andere bewegt, daher werden alle zusammen importiert.</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="35"/>
        <source>These are Blender&apos;s takes, one for every object and action: each object gets its own action.</source>
        <translation>Dies sind Takes von Blender, einer für jedes Objekt und jede Aktion: Jedes Objekt erhält seine eigene Aktion.</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="38"/>
        <source>These animations move the same nodes: choose which to import. Checked ones are merged; a node that several move takes the keys of the last one in the list.</source>
        <translation>Diese Animationen bewegen dieselben Knoten: Wählen Sie, welche importiert werden. Angehakte werden zusammengeführt; ein Knoten, den mehrere bewegen, erhält die Schlüsselbilder der letzten in der Liste.</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="46"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="66"/>
        <source>Euler filter: rotations in Euler mode (extrinsic xyz), angles continuous</source>
        <translation>Euler-Filter: Rotationen im Euler-Modus (extrinsisch xyz), Winkel stetig</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="70"/>
        <source>Import %1</source>
        <translation>%1 importieren</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="76"/>
        <source>Animation</source>
        <translation>Animation</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="76"/>
        <source>Length</source>
        <translation>Dauer</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="76"/>
        <source>Moves</source>
        <translation>Bewegte Knoten</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="79"/>
        <source>(unnamed %1)</source>
        <translation>(unbenannt %1)</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="104"/>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="107"/>
        <source>Frame rate:</source>
        <translation>Bildrate:</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="111"/>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="114"/>
        <source>One unit of the file:</source>
        <translation>Eine Einheit der Datei:</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="116"/>
        <source>Y up (turned to Z up)</source>
        <translation>Y oben (gedreht zu Z oben)</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="117"/>
        <source>Z up</source>
        <translation>Z oben</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="120"/>
        <source>Up axis:</source>
        <translation>Hochachse:</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="122"/>
        <source>First key at 0 s</source>
        <translation>Erstes Schlüsselbild bei 0 s</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="123"/>
        <source>As in the file</source>
        <translation>Wie in der Datei</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="124"/>
        <source>Time:</source>
        <translation>Zeit:</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="127"/>
        <source>Stores each imported rotation as Euler angles, Blender&apos;s default XYZ order, each key&apos;s angles the nearest to the key before, so that a spin is a ramp, not a saw-tooth</source>
        <translation>Speichert jede importierte Rotation als Euler-Winkel in Blenders Standardreihenfolge XYZ, die Winkel jedes Keys am nächsten an denen des vorigen, sodass eine Drehung eine Rampe ist, kein Sägezahn</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="129"/>
        <source>Rotations:</source>
        <translation>Rotationen:</translation>
    </message>
    <message>
        <location filename="../src/app/import_dialog.cpp" line="131"/>
        <source>From the file: %1; %2; %3.</source>
        <translation>Aus der Datei: %1; %2; %3.</translation>
    </message>
</context>
<context>
    <name>gyre::app::InspectorWidget</name>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="79"/>
        <source>time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="81"/>
        <source>position x</source>
        <translation>Position x</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="81"/>
        <source>position y</source>
        <translation>Position y</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="81"/>
        <source>position z</source>
        <translation>Position z</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="84"/>
        <source>quaternion w</source>
        <translation>Quaternion w</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="84"/>
        <source>quaternion x</source>
        <translation>Quaternion x</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="84"/>
        <source>quaternion y</source>
        <translation>Quaternion y</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="84"/>
        <source>quaternion z</source>
        <translation>Quaternion z</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="91"/>
        <source>matrix row %1, column %2</source>
        <translation>Matrix Zeile %1, Spalte %2</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="94"/>
        <source>axis x</source>
        <translation>Achse x</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="94"/>
        <source>axis y</source>
        <translation>Achse y</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="94"/>
        <source>axis z</source>
        <translation>Achse z</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="94"/>
        <source>angle</source>
        <translation>Winkel</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="96"/>
        <source>first angle</source>
        <translation>erster Winkel</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="96"/>
        <source>second angle</source>
        <translation>zweiter Winkel</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="96"/>
        <source>third angle</source>
        <translation>dritter Winkel</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="132"/>
        <source>Quaternions</source>
        <translation>Quaternionen</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="133"/>
        <source>Euler angles</source>
        <translation>Euler-Winkel</translation>
    </message>
    <message>
        <location filename="../src/app/euler_convention_choosers.cpp" line="29"/>
        <source>extrinsic (fixed axes)</source>
        <translation>extrinsisch (feste Achsen)</translation>
    </message>
    <message>
        <location filename="../src/app/euler_convention_choosers.cpp" line="31"/>
        <source>intrinsic (moving axes)</source>
        <translation>intrinsisch (mitbewegte Achsen)</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="158"/>
        <source>about %1 (°)</source>
        <translation>um %1 (°)</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="183"/>
        <source>The rotation mode was not changed: %1.</source>
        <translation>Der Rotationsmodus wurde nicht geändert: %1.</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="207"/>
        <source>%1, keyframe %2 of %3</source>
        <translation>%1, Schlüsselbild %2 von %3</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="244"/>
        <source>Near gimbal lock (%1° from it): the first and third angles turn about almost the same axis, so only their sum (or difference) is determined. Small changes of the rotation can swing them widely.</source>
        <translation>Nahe am Gimbal Lock (kardanische Blockade, %1° entfernt): Der erste und der dritte Winkel drehen fast um dieselbe Achse, daher ist nur ihre Summe (oder Differenz) bestimmt. Kleine Änderungen der Rotation können sie stark ausschlagen lassen.</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="286"/>
        <source>The keyframe was not moved: %1.</source>
        <translation>Das Schlüsselbild wurde nicht verschoben: %1.</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="297"/>
        <source>The constraint was not changed: %1.</source>
        <translation>Die Fixierung wurde nicht geändert: %1.</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="305"/>
        <source>The position was not changed: %1.</source>
        <translation>Die Position wurde nicht geändert: %1.</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="317"/>
        <location filename="../src/app/inspector_widget.cpp" line="340"/>
        <location filename="../src/app/inspector_widget.cpp" line="366"/>
        <location filename="../src/app/inspector_widget.cpp" line="389"/>
        <source>The rotation was not changed: %1.</source>
        <translation>Die Rotation wurde nicht geändert: %1.</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="322"/>
        <source>The rotation was not changed: the zero quaternion is no rotation.</source>
        <translation>Die Rotation wurde nicht geändert: Das Null-Quaternion ist keine Rotation.</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="330"/>
        <source>The quaternion had length %1; it was scaled to length 1.</source>
        <translation>Das Quaternion hatte die Länge %1; es wurde auf Länge 1 skaliert.</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="347"/>
        <source>The rotation was not changed: the matrix has determinant %1, so it flattens or mirrors space and is not a rotation.</source>
        <translation>Die Rotation wurde nicht geändert: Die Matrix hat die Determinante %1, sie staucht oder spiegelt also den Raum und ist keine Rotation.</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="355"/>
        <source>The matrix was not a rotation (its rows were up to %1 from orthonormal); the nearest rotation was used.</source>
        <translation>Die Matrix war keine Rotation (ihre Zeilen wichen um bis zu %1 von orthonormal ab); die nächstgelegene Rotation wurde verwendet.</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="372"/>
        <source>The rotation was not changed: a zero axis names no direction to turn about.</source>
        <translation>Die Rotation wurde nicht geändert: Eine Nullachse gibt keine Drehrichtung an.</translation>
    </message>
    <message>
        <location filename="../src/app/inspector_widget.cpp" line="377"/>
        <source>The axis had length %1; it was scaled to length 1.</source>
        <translation>Die Achse hatte die Länge %1; sie wurde auf Länge 1 skaliert.</translation>
    </message>
</context>
<context>
    <name>gyre::app::KeyClipboardActions</name>
    <message>
        <location filename="../src/app/key_clipboard_actions.cpp" line="55"/>
        <source>Cannot copy the pose: %1</source>
        <translation>Pose kann nicht kopiert werden: %1</translation>
    </message>
    <message>
        <location filename="../src/app/key_clipboard_actions.cpp" line="93"/>
        <location filename="../src/app/key_clipboard_actions.cpp" line="134"/>
        <source>Cannot paste: %1</source>
        <translation>Einfügen nicht möglich: %1</translation>
    </message>
    <message>
        <location filename="../src/app/key_clipboard_actions.cpp" line="114"/>
        <source>Cannot paste: no selected object has the name of a copied one</source>
        <translation>Einfügen nicht möglich: kein ausgewähltes Objekt trägt den Namen eines kopierten</translation>
    </message>
    <message>
        <location filename="../src/app/key_clipboard_actions.cpp" line="115"/>
        <source>Cannot paste: no object is selected</source>
        <translation>Einfügen nicht möglich: kein Objekt ist ausgewählt</translation>
    </message>
</context>
<context>
    <name>gyre::app::KeyframeActions</name>
    <message>
        <location filename="../src/app/keyframe_actions.cpp" line="77"/>
        <source>Cannot add a keyframe: %1</source>
        <translation>Schlüsselbild kann nicht hinzugefügt werden: %1</translation>
    </message>
    <message>
        <location filename="../src/app/keyframe_actions.cpp" line="133"/>
        <source>Apply Euler Filter</source>
        <translation>Euler-Filter anwenden</translation>
    </message>
    <message>
        <location filename="../src/app/keyframe_actions.cpp" line="149"/>
        <source>This span has a single free flight</source>
        <translation>Dieser Abschnitt hat nur einen freien Flug</translation>
    </message>
    <message>
        <location filename="../src/app/keyframe_actions.cpp" line="151"/>
        <source>Cannot step the flight: %1</source>
        <translation>Flug kann nicht gewechselt werden: %1</translation>
    </message>
</context>
<context>
    <name>gyre::app::MagnitudePlot</name>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="151"/>
        <source>Select an object to see and sketch the speed of its rotation.</source>
        <translation>Wählen Sie ein Objekt, um die Geschwindigkeit seiner Rotation zu sehen und zu skizzieren.</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="225"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="230"/>
        <source>Draw</source>
        <translation>Zeichnen</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="231"/>
        <source>Left-drag draws the magnitude |ω| over time; going back erases</source>
        <translation>Ziehen mit der linken Maustaste zeichnet den Betrag |ω| über der Zeit; zurückziehen radiert</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="232"/>
        <source>Pan</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="232"/>
        <source>Left-drag pans the view</source>
        <translation>Ziehen mit der linken Maustaste verschiebt die Ansicht</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="241"/>
        <source>Fit View</source>
        <translation>Ansicht einpassen</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="242"/>
        <source>Show the scene&apos;s time range and the curves&apos; height; double-click does too</source>
        <translation>Den Zeitbereich der Szene und die Höhe der Kurven zeigen; ein Doppelklick tut das auch</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="244"/>
        <source>Clear Magnitude</source>
        <translation>Betrag löschen</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="245"/>
        <source>Remove the sketched magnitude curve</source>
        <translation>Die skizzierte Betragskurve entfernen</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="259"/>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="260"/>
        <source>|ω| (rad/s)</source>
        <translation>|ω| (rad/s)</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="263"/>
        <source>|ω| (°/s)</source>
        <translation>|ω| (°/s)</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="276"/>
        <source>before fit</source>
        <translation>vor der Anpassung</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="277"/>
        <source>current</source>
        <translation>aktuell</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="278"/>
        <source>fitted</source>
        <translation>angepasst</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="279"/>
        <source>sketched</source>
        <translation>skizziert</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="280"/>
        <source>constrained keys</source>
        <translation>fixierte Schlüsselbilder</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/magnitude_plot.cpp" line="282"/>
        <source>free keys</source>
        <translation>freie Schlüsselbilder</translation>
    </message>
</context>
<context>
    <name>gyre::app::MainWindow</name>
    <message>
        <location filename="../src/app/main_window.cpp" line="72"/>
        <source>Gyre projects (*.gyre)</source>
        <translation>Gyre-Projekte (*.gyre)</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="181"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="185"/>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="209"/>
        <source>&lt;opened&gt;</source>
        <translation>&lt;geöffnet&gt;</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="293"/>
        <source>The 3D viewport needs OpenGL 3.3, which this display does not offer. Editing, the panels and the timeline work without it.</source>
        <translation>Das 3D-Ansichtsfenster braucht OpenGL 3.3, das diese Anzeige nicht bietet. Bearbeiten, die Bedienfelder und die Zeitleiste funktionieren ohne.</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="346"/>
        <source>Viewport frame rate while something moves, and the time to subdivide the trail: on the worker, and from the request to its arrival</source>
        <translation>Bildrate des Ansichtsfensters, während sich etwas bewegt, und die Zeit zum Unterteilen der Stroboskopspur: im Hintergrund-Thread und von der Anforderung bis zum Eintreffen</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="356"/>
        <source>%1 fps · subdivision %2 ms (%3 ms to arrive)</source>
        <translation>%1 fps · Unterteilung %2 ms (%3 ms bis zur Ankunft)</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="400"/>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="402"/>
        <source>%1[*] — Gyre</source>
        <translation>%1[*] — Gyre</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="417"/>
        <source>Open Project</source>
        <translation>Projekt öffnen</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="435"/>
        <source>Cannot open the project</source>
        <translation>Das Projekt kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="458"/>
        <source>L-shaped cycle (ScrewBender)</source>
        <translation>L-förmiger Zyklus (ScrewBender)</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="459"/>
        <source>Spinning top (sketched angular velocity)</source>
        <translation>Kreisel (skizzierte Winkelgeschwindigkeit)</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="460"/>
        <source>Letter M (sketched angular velocity)</source>
        <translation>Buchstabe M (skizzierte Winkelgeschwindigkeit)</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="461"/>
        <source>Hat (sketched angular velocity)</source>
        <translation>Hut (skizzierte Winkelgeschwindigkeit)</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="462"/>
        <source>Falling leaf (sketched angular velocity)</source>
        <translation>Fallendes Blatt (skizzierte Winkelgeschwindigkeit)</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="463"/>
        <source>Pen (sketched angular speed)</source>
        <translation>Stift (skizzierter Betrag der Winkelgeschwindigkeit)</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="464"/>
        <source>Pendulum (ScrewBender)</source>
        <translation>Pendel (ScrewBender)</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="465"/>
        <source>Spinning block (ScrewBender)</source>
        <translation>Rotierender Block (ScrewBender)</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="466"/>
        <source>Critter&apos;s non-planar cycle (ScrewBender)</source>
        <translation>Nicht-ebener Zyklus eines Tierchens (ScrewBender)</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="467"/>
        <source>Tossed T-handle (free flight)</source>
        <translation>Geworfener T-Griff (freier Flug)</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="468"/>
        <source>Flipped coin (free flight)</source>
        <translation>Geworfene Münze (freier Flug)</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="469"/>
        <source>Thrown book (free flight)</source>
        <translation>Geworfenes Buch (freier Flug)</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="488"/>
        <source>Save Project As</source>
        <translation>Projekt speichern unter</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="501"/>
        <source>Cannot save the project</source>
        <translation>Das Projekt kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="505"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="514"/>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="514"/>
        <source>The project has unsaved changes. Save them first?</source>
        <translation>Das Projekt hat ungespeicherte Änderungen. Zuerst speichern?</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="553"/>
        <source>About Gyre</source>
        <translation>Über Gyre</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="554"/>
        <source>&lt;h3&gt;Gyre %1&lt;/h3&gt;&lt;p&gt;Edit the rotations of animated rigid objects: every way of writing an orientation, interpolation that behaves, sketched angular velocity, and ScrewBender motions.&lt;/p&gt;&lt;p&gt;Built on Qt %2, Eigen %3.%4.%5, Ceres Solver %6, Assimp %7 and QCustomPlot %8.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Gyre %1&lt;/h3&gt;&lt;p&gt;Rotationen animierter starrer Objekte bearbeiten: jede Schreibweise einer Orientierung, Interpolation, die sich gut verhält, skizzierte Winkelgeschwindigkeit und ScrewBender-Bewegungen.&lt;/p&gt;&lt;p&gt;Aufgebaut auf Qt %2, Eigen %3.%4.%5, Ceres Solver %6, Assimp %7 und QCustomPlot %8.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="574"/>
        <source>Autosave failed: %1</source>
        <translation>Automatische Sicherung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="583"/>
        <source>an untitled project</source>
        <translation>ein unbenanntes Projekt</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="586"/>
        <source>Recover unsaved work</source>
        <translation>Ungesicherte Arbeit wiederherstellen</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="587"/>
        <source>Gyre ended without saving changes to %1 (last copy %2). Recover them?</source>
        <translation>Gyre wurde beendet, ohne Änderungen an %1 zu speichern (letzte Kopie %2). Wiederherstellen?</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="602"/>
        <source>Cannot recover</source>
        <translation>Wiederherstellen nicht möglich</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="577"/>
        <source>Autosave is off: %1</source>
        <translation>Automatische Sicherung ist aus: %1</translation>
    </message>
    <message>
        <location filename="../src/app/main_window.cpp" line="213"/>
        <source>Outliner</source>
        <translation>Gliederung</translation>
    </message>
</context>
<context>
    <name>gyre::app::MassPropertiesGroup</name>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="47"/>
        <source>Body</source>
        <translation>Körper</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="51"/>
        <source>Type values</source>
        <translation>Werte eingeben</translation>
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
        <translation>Masse</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="72"/>
        <source>centre x</source>
        <translation>Schwerpunkt x</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="72"/>
        <source>centre y</source>
        <translation>Schwerpunkt y</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="72"/>
        <source>centre z</source>
        <translation>Schwerpunkt z</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="78"/>
        <source>Mass (kg)</source>
        <translation>Masse (kg)</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="79"/>
        <source>Centre (m)</source>
        <translation>Schwerpunkt (m)</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="80"/>
        <source>Inertia (kg·m²)</source>
        <translation>Trägheit (kg·m²)</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="81"/>
        <source>Principal</source>
        <translation>Hauptmomente</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="122"/>
        <source>%1, %2, %3 kg·m²</source>
        <translation>%1, %2, %3 kg·m²</translation>
    </message>
    <message>
        <location filename="../src/app/mass_properties_group.cpp" line="156"/>
        <location filename="../src/app/mass_properties_group.cpp" line="168"/>
        <source>Not changed: %1</source>
        <translation>Nicht geändert: %1</translation>
    </message>
</context>
<context>
    <name>gyre::app::NumberFields</name>
    <message>
        <location filename="../src/app/number_fields.cpp" line="49"/>
        <source>Exact value: %1</source>
        <translation>Exakter Wert: %1</translation>
    </message>
</context>
<context>
    <name>gyre::app::OffscreenGlWidget</name>
    <message>
        <location filename="../src/app/viewport/offscreen_gl_widget.cpp" line="33"/>
        <source>The display could not make an offscreen surface for OpenGL.</source>
        <translation>Die Anzeige konnte keine Offscreen-Oberfläche für OpenGL anlegen.</translation>
    </message>
    <message>
        <location filename="../src/app/viewport/offscreen_gl_widget.cpp" line="35"/>
        <source>The display could not make an OpenGL %1.%2 context.</source>
        <translation>Die Anzeige konnte keinen OpenGL-%1.%2-Kontext anlegen.</translation>
    </message>
    <message>
        <location filename="../src/app/viewport/offscreen_gl_widget.cpp" line="39"/>
        <source>The display could not make its OpenGL context current.</source>
        <translation>Die Anzeige konnte ihren OpenGL-Kontext nicht aktivieren.</translation>
    </message>
    <message>
        <location filename="../src/app/viewport/offscreen_gl_widget.cpp" line="73"/>
        <source>OpenGL could not make a framebuffer of %1 × %2 pixels.</source>
        <translation>OpenGL konnte keinen Framebuffer von %1 × %2 Pixeln anlegen.</translation>
    </message>
</context>
<context>
    <name>gyre::app::OutlinerPanel</name>
    <message>
        <location filename="../src/app/outliner/outliner_panel.cpp" line="28"/>
        <source>Filter by name</source>
        <translation>Nach Namen filtern</translation>
    </message>
    <message numerus="yes">
        <location filename="../src/app/outliner/outliner_panel.cpp" line="141"/>
        <source>Delete %n Objects</source>
        <translation>
            <numerusform>%n Objekt löschen</numerusform>
            <numerusform>%n Objekte löschen</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>gyre::app::PatternCanvas</name>
    <message>
        <location filename="../src/app/sketch/pattern_pad.cpp" line="34"/>
        <source>Draw the pattern once, left to right: x along the strokes, y across them</source>
        <translation>Das Muster einmal von links nach rechts zeichnen: x entlang der Striche, y quer dazu</translation>
    </message>
</context>
<context>
    <name>gyre::app::PatternPad</name>
    <message>
        <location filename="../src/app/sketch/pattern_pad.cpp" line="146"/>
        <source>Clear Pattern</source>
        <translation>Muster löschen</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/pattern_pad.cpp" line="150"/>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/pattern_pad.cpp" line="151"/>
        <source>How many times the pattern repeats along the direction curve; off: not applied</source>
        <translation>Wie oft sich das Muster entlang der Richtungskurve wiederholt; aus: nicht angewendet</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/pattern_pad.cpp" line="152"/>
        <source>Take the pattern away</source>
        <translation>Das Muster entfernen</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/pattern_pad.cpp" line="153"/>
        <source>&amp;Repeat:</source>
        <translation>&amp;Wiederholen:</translation>
    </message>
</context>
<context>
    <name>gyre::app::PreferencesDialog</name>
    <message>
        <location filename="../src/app/preferences_dialog.cpp" line="22"/>
        <source>System default</source>
        <translation>Systemstandard</translation>
    </message>
</context>
<context>
    <name>gyre::app::SceneFileActions</name>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="30"/>
        <source>Scenes (*.fbx *.gltf *.glb *.dae *.obj *.bvh *.3ds *.x *.ase *.ply *.stl);;All files (*)</source>
        <translation>Szenen (*.fbx *.gltf *.glb *.dae *.obj *.bvh *.3ds *.x *.ase *.ply *.stl);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="36"/>
        <source>glTF 2.0 (*.gltf);;glTF 2.0 binary (*.glb);;Collada (*.dae);;FBX (*.fbx);;OBJ, meshes only (*.obj)</source>
        <translation>glTF 2.0 (*.gltf);;glTF 2.0 binär (*.glb);;Collada (*.dae);;FBX (*.fbx);;OBJ, nur Meshes (*.obj)</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="63"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="80"/>
        <location filename="../src/app/scene_file_actions.cpp" line="147"/>
        <source>Import of %1 cancelled</source>
        <translation>Import von %1 abgebrochen</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="86"/>
        <source>Import Scene</source>
        <translation>Szene importieren</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="94"/>
        <source>Export Scene</source>
        <translation>Szene exportieren</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="108"/>
        <location filename="../src/app/scene_file_actions.cpp" line="119"/>
        <location filename="../src/app/scene_file_actions.cpp" line="165"/>
        <source>Wait for the scene file being read or written first</source>
        <translation>Warten Sie zuerst, bis die Szenendatei gelesen oder geschrieben ist</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="122"/>
        <source>Importing %1…</source>
        <translation>%1 wird importiert…</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="157"/>
        <source>Cannot export</source>
        <translation>Export nicht möglich</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="158"/>
        <source>%1: Gyre writes .gltf, .glb, .dae, .fbx and .obj scenes; the file name&apos;s extension says which.</source>
        <translation>%1: Gyre schreibt Szenen als .gltf, .glb, .dae, .fbx und .obj; die Endung des Dateinamens bestimmt das Format.</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="168"/>
        <source>Exporting %1…</source>
        <translation>%1 wird exportiert…</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="175"/>
        <source>%1: the file holds no objects.</source>
        <translation>%1: Die Datei enthält keine Objekte.</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="178"/>
        <source>Import %1</source>
        <translation>%1 importieren</translation>
    </message>
    <message numerus="yes">
        <location filename="../src/app/scene_file_actions.cpp" line="197"/>
        <source>Objects imported from %1: %n</source>
        <translation>
            <numerusform>%n Objekt aus %1 importiert</numerusform>
            <numerusform>%n Objekte aus %1 importiert</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="200"/>
        <source>Imported %1</source>
        <translation>%1 importiert</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="206"/>
        <location filename="../src/app/scene_file_actions.cpp" line="207"/>
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <location filename="../src/app/scene_file_actions.cpp" line="213"/>
        <source>Scene file</source>
        <translation>Szenendatei</translation>
    </message>
    <message numerus="yes">
        <location filename="../src/app/scene_file_actions.cpp" line="222"/>
        <source>Done. Warnings about what the file could not keep: %n.</source>
        <translation>
            <numerusform>Fertig, mit %n Warnung dazu, was die Datei nicht aufnehmen konnte.</numerusform>
            <numerusform>Fertig, mit %n Warnungen dazu, was die Datei nicht aufnehmen konnte.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>gyre::app::SceneTreeModel</name>
    <message>
        <location filename="../src/app/outliner/scene_tree_model.cpp" line="135"/>
        <source>Shown in the viewport: uncheck to hide it</source>
        <translation>Im Ansichtsfenster sichtbar: abwählen, um es auszublenden</translation>
    </message>
    <message>
        <location filename="../src/app/outliner/scene_tree_model.cpp" line="135"/>
        <source>Hidden in the viewport: check to show it</source>
        <translation>Im Ansichtsfenster ausgeblendet: anhaken, um es einzublenden</translation>
    </message>
    <message numerus="yes">
        <location filename="../src/app/outliner/scene_tree_model.cpp" line="309"/>
        <source>Reparent %n Objects in Place</source>
        <translation>
            <numerusform>%n Objekt an Ort und Stelle umhängen</numerusform>
            <numerusform>%n Objekte an Ort und Stelle umhängen</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>gyre::app::ScrewBenderPanel</name>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="26"/>
        <source>Slerp (great arcs)</source>
        <translation>Slerp (Großkreisbögen)</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="28"/>
        <source>Nlerp (normalised straight lines)</source>
        <translation>Nlerp (normierte Geraden)</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="30"/>
        <source>Squad (smooth quaternion curve)</source>
        <translation>Squad (glatte Quaternion-Kurve)</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="32"/>
        <source>Hermite quaternion spline</source>
        <translation>Hermite-Quaternion-Spline</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="34"/>
        <source>Euler angles, linearly</source>
        <translation>Euler-Winkel, linear</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="36"/>
        <source>Euler angles, smooth (automatic tangents)</source>
        <translation>Euler-Winkel, glatt (automatische Tangenten)</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="38"/>
        <source>Screw motion (ScrewBender)</source>
        <translation>Schraubbewegung (ScrewBender)</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="40"/>
        <source>Ballistic (free flight between keys)</source>
        <translation>Ballistisch (freier Flug zwischen Keys)</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="50"/>
        <source>Four-point</source>
        <translation>Vierpunkt</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="52"/>
        <source>Four-point B</source>
        <translation>Vierpunkt B</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="54"/>
        <source>Cubic B-spline</source>
        <translation>Kubischer B-Spline</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="56"/>
        <source>Jarek</source>
        <translation>Jarek</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="146"/>
        <source>%1 from %2 keyframes</source>
        <translation>%1 aus %2 Schlüsselbildern</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="147"/>
        <source>too many to hold, from %1 keyframes</source>
        <translation>zu viele zum Speichern, aus %1 Schlüsselbildern</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="159"/>
        <source>The interpolation was not changed: %1.</source>
        <translation>Die Interpolation wurde nicht geändert: %1.</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="172"/>
        <source>Interpolate by Screws</source>
        <translation>Per Schraubbewegung interpolieren</translation>
    </message>
    <message>
        <location filename="../src/app/screwbender_panel.cpp" line="196"/>
        <source>The subdivision was not changed: %1.</source>
        <translation>Die Unterteilung wurde nicht geändert: %1.</translation>
    </message>
</context>
<context>
    <name>gyre::app::SmoothnessPanel</name>
    <message>
        <location filename="../src/app/smoothness_panel.cpp" line="29"/>
        <source>position
(units)</source>
        <translation>Position
(Einheiten)</translation>
    </message>
    <message>
        <location filename="../src/app/smoothness_panel.cpp" line="31"/>
        <source>velocity
(units/s)</source>
        <translation>Geschwindigkeit
(Einheiten/s)</translation>
    </message>
    <message>
        <location filename="../src/app/smoothness_panel.cpp" line="33"/>
        <source>acceleration
(units/s²)</source>
        <translation>Beschleunigung
(Einheiten/s²)</translation>
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
        <translation>Betrag</translation>
    </message>
    <message>
        <location filename="../src/app/smoothness_panel.cpp" line="106"/>
        <source>Point of the object (local):</source>
        <translation>Punkt des Objekts (lokal):</translation>
    </message>
    <message>
        <location filename="../src/app/smoothness_panel.cpp" line="113"/>
        <source>%1 </source>
        <translation>%1 </translation>
    </message>
    <message>
        <location filename="../src/app/smoothness_panel.cpp" line="116"/>
        <source>The %1 coordinate of the plotted point, in the object&apos;s frame</source>
        <translation>Die %1-Koordinate des dargestellten Punkts im Koordinatensystem des Objekts</translation>
    </message>
    <message>
        <location filename="../src/app/smoothness_panel.cpp" line="164"/>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
</context>
<context>
    <name>gyre::app::SphereView</name>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="192"/>
        <source>Draw</source>
        <translation>Zeichnen</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="193"/>
        <source>Draw the direction of the angular velocity on the front of the sphere</source>
        <translation>Die Richtung der Winkelgeschwindigkeit auf die Vorderseite der Kugel zeichnen</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="194"/>
        <source>Erase</source>
        <translation>Radieren</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="194"/>
        <source>Erase the strokes&apos; points under the pointer</source>
        <translation>Die Punkte der Striche unter dem Zeiger radieren</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="195"/>
        <source>Pattern</source>
        <translation>Muster</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="196"/>
        <source>Draw a pattern to repeat along the strokes, on the pad</source>
        <translation>Auf dem Feld ein Muster zeichnen, das sich entlang der Striche wiederholt</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="199"/>
        <source>Reset View</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="202"/>
        <source>Turn the sphere back to its first view, z up (R)</source>
        <translation>Die Kugel in ihre erste Ansicht zurückdrehen, z oben (R)</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="246"/>
        <source>Select an object to sketch the direction of its angular velocity.</source>
        <translation>Wählen Sie ein Objekt, um die Richtung seiner Winkelgeschwindigkeit zu skizzieren.</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="248"/>
        <source>%1 does not turn: key it in two orientations to give it an angular velocity to sketch.</source>
        <translation>%1 dreht sich nicht: Setzen Sie Schlüsselbilder in zwei Orientierungen, damit es eine Winkelgeschwindigkeit zum Skizzieren hat.</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="623"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="656"/>
        <source>motion: ω/|ω|</source>
        <translation>Bewegung: ω/|ω|</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="658"/>
        <source>fitted</source>
        <translation>angepasst</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="659"/>
        <source>before the fit</source>
        <translation>vor der Anpassung</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="661"/>
        <source>sketch as drawn</source>
        <translation>Skizze wie gezeichnet</translation>
    </message>
    <message>
        <location filename="../src/app/sketch/sphere_view.cpp" line="662"/>
        <source>sketch as fitted, pattern applied</source>
        <translation>Skizze wie angepasst, mit Muster</translation>
    </message>
</context>
<context>
    <name>gyre::app::TimeBar</name>
    <message>
        <location filename="../src/app/time_bar.cpp" line="29"/>
        <source> s</source>
        <translation> s</translation>
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
        <translation>Wie schnell der Schwerpunkt einer ballistischen Spur fällt</translation>
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
        <translation>Die Oben-Achse der Szene: die Schwerkraft zieht in die Gegenrichtung</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="67"/>
        <source>Frames per second</source>
        <translation>Frames pro Sekunde</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="68"/>
        <source>Where the scene starts</source>
        <translation>Wo die Szene beginnt</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="69"/>
        <source>Where the scene ends</source>
        <translation>Wo die Szene endet</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="71"/>
        <location filename="../src/app/time_bar.cpp" line="113"/>
        <source>Time %1 s</source>
        <translation>Zeit %1 s</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="72"/>
        <location filename="../src/app/time_bar.cpp" line="115"/>
        <source>Frame %1</source>
        <translation>Frame %1</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="79"/>
        <source>Rate</source>
        <translation>Bildrate</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="79"/>
        <source>Start</source>
        <translation>Anfang</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="80"/>
        <source>End</source>
        <translation>Ende</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="80"/>
        <source>Gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <location filename="../src/app/time_bar.cpp" line="81"/>
        <source>Up</source>
        <translation>Oben</translation>
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
        <translation>%1 f</translation>
    </message>
</context>
<context>
    <name>gyre::app::Translations</name>
    <message>
        <location filename="../src/app/language.cpp" line="59"/>
        <source>Gyre does not speak the language &quot;%1&quot; and speaks English instead.</source>
        <translation>Gyre spricht die Sprache „%1“ nicht und spricht stattdessen Englisch.</translation>
    </message>
</context>
<context>
    <name>gyre::app::ViewPreferences</name>
    <message>
        <location filename="../src/app/view_preferences.cpp" line="61"/>
        <source>Trail</source>
        <translation>Spur</translation>
    </message>
    <message numerus="yes">
        <location filename="../src/app/view_preferences.cpp" line="65"/>
        <source>%n Copies</source>
        <translation>
            <numerusform>%n Kopie</numerusform>
            <numerusform>%n Kopien</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../src/app/view_preferences.cpp" line="68"/>
        <source>Over the Whole Range</source>
        <translation>Über den ganzen Bereich</translation>
    </message>
    <message numerus="yes">
        <location filename="../src/app/view_preferences.cpp" line="68"/>
        <source>Every %n Frame(s) About the Current Frame</source>
        <translation>
            <numerusform>Jedes %n. Frame um das aktuelle Frame</numerusform>
            <numerusform>Alle %n Frames um das aktuelle Frame</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../src/app/view_preferences.cpp" line="71"/>
        <source>Y Up</source>
        <translation>Y oben</translation>
    </message>
    <message>
        <location filename="../src/app/view_preferences.cpp" line="74"/>
        <source>Show the scene with y up, as Maya does: orbit about y, the grid across it, the front view along −z</source>
        <translation>Die Szene mit y oben zeigen, wie Maya: um y kreisen, das Gitter quer dazu, die Vorderansicht entlang −z</translation>
    </message>
</context>
<context>
    <name>gyre::model::Command</name>
    <message>
        <location filename="../src/model/commands/add_stroke_command.cpp" line="11"/>
        <source>Add Stroke</source>
        <translation>Strich hinzufügen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/apply_fit_result_command.cpp" line="53"/>
        <source>Apply angular velocity fit</source>
        <translation>Anpassung der Winkelgeschwindigkeit anwenden</translation>
    </message>
    <message>
        <location filename="../src/model/commands/remove_fit_command.cpp" line="20"/>
        <source>Remove angular velocity fit</source>
        <translation>Anpassung der Winkelgeschwindigkeit entfernen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/delete_object_command.cpp" line="25"/>
        <source>Delete Object</source>
        <translation>Objekt löschen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/edit_stroke_command.cpp" line="11"/>
        <source>Edit Stroke</source>
        <translation>Strich bearbeiten</translation>
    </message>
    <message>
        <location filename="../src/model/commands/erase_stroke_command.cpp" line="9"/>
        <source>Erase Stroke</source>
        <translation>Strich radieren</translation>
    </message>
    <message>
        <location filename="../src/model/commands/import_objects_command.cpp" line="95"/>
        <source>Import Objects</source>
        <translation>Objekte importieren</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_keyframe_time_command.cpp" line="33"/>
        <source>Move Keyframe</source>
        <translation>Schlüsselbild verschieben</translation>
    </message>
    <message>
        <location filename="../src/model/commands/rename_object_command.cpp" line="10"/>
        <source>Rename Object</source>
        <translation>Objekt umbenennen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/reparent_object_command.cpp" line="34"/>
        <source>Reparent Object</source>
        <translation>Objekt umhängen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/retime_keyframes_command.cpp" line="43"/>
        <source>Retime Keyframes</source>
        <translation>Schlüsselbilder neu timen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_fit_parameter_command.cpp" line="25"/>
        <source>Set Fit Parameter</source>
        <translation>Anpassungsparameter setzen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_fit_window_command.cpp" line="11"/>
        <source>Set Fit Window</source>
        <translation>Anpassungsfenster setzen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_interpolation_command.cpp" line="28"/>
        <source>Set Interpolation</source>
        <translation>Interpolation setzen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_keyframe_orientation_command.cpp" line="37"/>
        <location filename="../src/model/commands/set_keyframe_orientation_command.cpp" line="45"/>
        <source>Rotate Keyframe</source>
        <translation>Schlüsselbild drehen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_keyframe_position_command.cpp" line="11"/>
        <source>Move Keyframe Position</source>
        <translation>Position des Schlüsselbilds verschieben</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_magnitude_curve_command.cpp" line="11"/>
        <source>Draw Magnitude Curve</source>
        <translation>Betragskurve zeichnen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_pattern_command.cpp" line="21"/>
        <source>Draw Pattern</source>
        <translation>Muster zeichnen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_subdivision_command.cpp" line="24"/>
        <source>Set Subdivision</source>
        <translation>Unterteilung setzen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_time_range_command.cpp" line="20"/>
        <source>Set Time Range</source>
        <translation>Zeitbereich setzen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/toggle_keyframe_constraint_command.cpp" line="10"/>
        <source>Toggle Keyframe Constraint</source>
        <translation>Fixierung des Schlüsselbilds umschalten</translation>
    </message>
    <message>
        <location filename="../src/model/commands/reparent_object_in_place_command.cpp" line="30"/>
        <source>Reparent Object in Place</source>
        <translation>Objekt an Ort und Stelle umhängen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_object_visibility_command.cpp" line="10"/>
        <source>Show Object</source>
        <translation>Objekt einblenden</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_object_visibility_command.cpp" line="11"/>
        <source>Hide Object</source>
        <translation>Objekt ausblenden</translation>
    </message>
    <message>
        <location filename="../src/model/commands/apply_euler_filter_command.cpp" line="15"/>
        <source>Apply Euler Filter</source>
        <translation>Euler-Filter anwenden</translation>
    </message>
    <message>
        <location filename="../src/model/commands/replace_keyframes_command.cpp" line="21"/>
        <source>Delete Keyframes</source>
        <translation>Keyframes löschen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/replace_keyframes_command.cpp" line="23"/>
        <source>Insert Keyframes</source>
        <translation>Keyframes einfügen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/replace_keyframes_command.cpp" line="25"/>
        <source>Paste Keyframes</source>
        <translation>Keyframes einfügen (Zwischenablage)</translation>
    </message>
    <message>
        <location filename="../src/model/commands/replace_keyframes_command.cpp" line="27"/>
        <source>Move Keyframes</source>
        <translation>Keyframes verschieben</translation>
    </message>
    <message>
        <location filename="../src/model/commands/replace_keyframes_command.cpp" line="31"/>
        <source>Scale Keyframes</source>
        <translation>Keyframes skalieren</translation>
    </message>
    <message>
        <location filename="../src/model/commands/step_ballistic_solution_command.cpp" line="31"/>
        <source>Step Flight Solution</source>
        <translation>Flugbahn wechseln</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_mass_override_command.cpp" line="14"/>
        <source>Set Mass Properties</source>
        <translation>Masseeigenschaften setzen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_mass_override_command.cpp" line="15"/>
        <source>Mass From Mesh</source>
        <translation>Masse aus dem Mesh</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_rotation_mode_command.cpp" line="22"/>
        <source>Set Rotation Mode</source>
        <translation>Rotationsmodus setzen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_physics_target_command.cpp" line="25"/>
        <source>Set Physics Target</source>
        <translation>Physikziel setzen</translation>
    </message>
    <message>
        <location filename="../src/model/commands/set_gravity_command.cpp" line="10"/>
        <source>Set Gravity</source>
        <translation>Schwerkraft setzen</translation>
    </message>
</context>
<context>
    <name>gyre::model::Primitive</name>
    <message>
        <location filename="../src/model/primitive_meshes.cpp" line="166"/>
        <source>Block</source>
        <translation>Block</translation>
    </message>
    <message>
        <location filename="../src/model/primitive_meshes.cpp" line="168"/>
        <source>Box</source>
        <translation>Würfel</translation>
    </message>
    <message>
        <location filename="../src/model/primitive_meshes.cpp" line="170"/>
        <source>Disc</source>
        <translation>Scheibe</translation>
    </message>
    <message>
        <location filename="../src/model/primitive_meshes.cpp" line="172"/>
        <source>Cone</source>
        <translation>Kegel</translation>
    </message>
    <message>
        <location filename="../src/model/primitive_meshes.cpp" line="174"/>
        <source>Arrow</source>
        <translation>Pfeil</translation>
    </message>
</context>
<context>
    <name>gyre::model::SketchFitError</name>
    <message>
        <location filename="../src/model/sketch_fit_problem.cpp" line="95"/>
        <source>Direction stroke %1 cannot be followed: %2</source>
        <translation>Dem Richtungsstrich %1 kann nicht gefolgt werden: %2</translation>
    </message>
    <message>
        <location filename="../src/model/sketch_fit_problem.cpp" line="243"/>
        <source>The fit needs at least two keyframes on the selected object.</source>
        <translation>Die Anpassung braucht mindestens zwei Schlüsselbilder am gewählten Objekt.</translation>
    </message>
    <message>
        <location filename="../src/model/sketch_fit_problem.cpp" line="246"/>
        <source>Nothing is sketched yet: draw the direction of the angular velocity on the sphere, or its magnitude on the plot.</source>
        <translation>Noch ist nichts skizziert: Zeichnen Sie die Richtung der Winkelgeschwindigkeit auf die Kugel oder ihren Betrag in das Diagramm.</translation>
    </message>
    <message>
        <location filename="../src/model/sketch_fit_problem.cpp" line="251"/>
        <source>The edit window has no length inside the keys&apos; span: widen it, or sketch between the first and the last key.</source>
        <translation>Das Bearbeitungsfenster hat innerhalb des Bereichs der Schlüsselbilder keine Länge: Erweitern Sie es oder skizzieren Sie zwischen dem ersten und dem letzten Schlüsselbild.</translation>
    </message>
    <message>
        <location filename="../src/model/sketch_fit_problem.cpp" line="257"/>
        <source>The edit window of %1 s needs %2 target samples at %3 a second; the budget is %4: narrow the window.</source>
        <translation>Das Bearbeitungsfenster von %1 s braucht bei %3 pro Sekunde %2 Zielabtastwerte; erlaubt sind höchstens %4: Verkleinern Sie das Fenster.</translation>
    </message>
    <message>
        <location filename="../src/model/sketch_fit_problem.cpp" line="268"/>
        <source>The pattern cannot be repeated: %1</source>
        <translation>Das Muster kann nicht wiederholt werden: %1</translation>
    </message>
    <message>
        <location filename="../src/model/physics_target.cpp" line="27"/>
        <source>the physics target needs at least two keyframes</source>
        <translation>das Physikziel braucht mindestens zwei Keyframes</translation>
    </message>
    <message>
        <location filename="../src/model/physics_target.cpp" line="35"/>
        <source>the object is at rest at %1 s, so a free flight from there has no direction</source>
        <translation>das Objekt ruht bei %1 s, daher hat ein freier Flug von dort keine Richtung</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../src/app/main.cpp" line="26"/>
        <source>%1: cannot write the screenshot</source>
        <translation>%1: Das Bildschirmfoto kann nicht geschrieben werden</translation>
    </message>
    <message>
        <location filename="../src/app/main.cpp" line="53"/>
        <source>Edit the rotations of animated rigid objects.</source>
        <translation>Rotationen animierter starrer Objekte bearbeiten.</translation>
    </message>
    <message>
        <location filename="../src/app/main.cpp" line="58"/>
        <source>A Gyre project to open, or a scene file (FBX, glTF, ...) to import.</source>
        <translation>Ein zu öffnendes Gyre-Projekt oder eine zu importierende Szenendatei (FBX, glTF, ...).</translation>
    </message>
    <message>
        <location filename="../src/app/main.cpp" line="61"/>
        <source>Save a picture of the window to &lt;file&gt; after a few seconds, then quit.</source>
        <translation>Nach einigen Sekunden ein Bild des Fensters in &lt;file&gt; speichern und dann beenden.</translation>
    </message>
    <message>
        <location filename="../src/app/main.cpp" line="64"/>
        <source>Wait &lt;ms&gt; milliseconds before the screenshot.</source>
        <translation>Vor dem Bildschirmfoto &lt;ms&gt; Millisekunden warten.</translation>
    </message>
    <message>
        <location filename="../src/app/main.cpp" line="68"/>
        <source>Speak &lt;language&gt; (%1) instead of the one chosen in the preferences.</source>
        <translation>&lt;language&gt; sprechen (%1) statt der in den Einstellungen gewählten Sprache.</translation>
    </message>
    <message>
        <location filename="../src/app/main.cpp" line="76"/>
        <source>--delay takes a number of milliseconds, not &quot;%1&quot;.</source>
        <translation>--delay erwartet eine Anzahl Millisekunden, nicht „%1“.</translation>
    </message>
    <message>
        <location filename="../src/app/main.cpp" line="79"/>
        <source>give at most one file to open.</source>
        <translation>geben Sie höchstens eine Datei zum Öffnen an.</translation>
    </message>
</context>
</TS>
