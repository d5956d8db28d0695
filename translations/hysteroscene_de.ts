<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de">
<context>
    <name>hs::simapp::SimWindow</name>
    <message>
        <source>&amp;Polypectomy: resect the polyps with the loop</source>
        <translation>&amp;Polypektomie: die Polypen mit der Schlinge resezieren</translation>
    </message>
    <message>
        <source>&amp;Myomectomy: resect the submucous myomas with the loop</source>
        <translation>&amp;Myomektomie: die submukösen Myome mit der Schlinge resezieren</translation>
    </message>
    <message>
        <source>This device speaks version 1 of the hysteroscope protocol: it drives the diagnostic scope only. The resectoscope&apos;s loop, pedals and pump buttons need a device of version 2 (docs/haptics-protocol.md); without one the %1 exercise cannot cut.</source>
        <translation>Dieses Gerät spricht Version 1 des Hysteroskop-Protokolls: Es steuert nur das diagnostische Hysteroskop. Schlinge, Pedale und Pumpentasten des Resektoskops brauchen ein Gerät der Version 2 (docs/haptics-protocol.md); ohne ein solches kann in der Übung %1 nicht geschnitten werden.</translation>
    </message>
    <message>
        <source>&lt;p&gt;The instruments (polypectomy, myomectomy) and the pump:&lt;/p&gt;&lt;table&gt;&lt;tr&gt;&lt;td&gt;L&lt;/td&gt;&lt;td&gt;the next instrument: the resectoscope&apos;s loop, scissors, grasper, none&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;R / F&lt;/td&gt;&lt;td&gt;push the instrument out / draw it in (the working element)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;C, held&lt;/td&gt;&lt;td&gt;the cutting pedal (scissors and grasper: close the jaws)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;V, held&lt;/td&gt;&lt;td&gt;the coagulating pedal&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;+ / -&lt;/td&gt;&lt;td&gt;raise / lower the pump&apos;s set pressure by 5 mmHg&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;p&gt;Die Instrumente (Polypektomie, Myomektomie) und die Pumpe:&lt;/p&gt;&lt;table&gt;&lt;tr&gt;&lt;td&gt;L&lt;/td&gt;&lt;td&gt;das nächste Instrument: die Schlinge des Resektoskops, Schere, Fasszange, keines&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;R / F&lt;/td&gt;&lt;td&gt;das Instrument vorschieben / zurückziehen (der Arbeitseinsatz)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;C, gehalten&lt;/td&gt;&lt;td&gt;das Schneidpedal (Schere und Fasszange: die Branchen schließen)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;V, gehalten&lt;/td&gt;&lt;td&gt;das Koagulationspedal&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;+ / -&lt;/td&gt;&lt;td&gt;den Solldruck der Pumpe um 5 mmHg erhöhen / senken&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
    <message>
        <source>hysteroscene simulator</source>
        <translation>hysteroscene-Simulator</translation>
    </message>
    <message>
        <source>Open a scene package (File &gt; Open).</source>
        <translation>Ein Szenenpaket öffnen (Datei &gt; Paket öffnen).</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Open Package...</source>
        <translation>Paket ö&amp;ffnen...</translation>
    </message>
    <message>
        <source>&amp;End Trial and Show Report...</source>
        <translation>&amp;Durchlauf beenden und Bericht anzeigen...</translation>
    </message>
    <message>
        <source>&amp;Restart Trial</source>
        <translation>Durchlauf &amp;neu starten</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Scope</source>
        <translation>Hystero&amp;skop</translation>
    </message>
    <message>
        <source>&amp;Optic</source>
        <translation>&amp;Optik</translation>
    </message>
    <message>
        <source>0°</source>
        <translation>0°</translation>
    </message>
    <message>
        <source>12°</source>
        <translation>12°</translation>
    </message>
    <message>
        <source>30°</source>
        <translation>30°</translation>
    </message>
    <message>
        <source>&amp;Diameter</source>
        <translation>&amp;Durchmesser</translation>
    </message>
    <message>
        <source>2.9 mm</source>
        <translation>2,9 mm</translation>
    </message>
    <message>
        <source>4 mm</source>
        <translation>4 mm</translation>
    </message>
    <message>
        <source>5 mm</source>
        <translation>5 mm</translation>
    </message>
    <message>
        <source>&amp;Exercise</source>
        <translation>Ü&amp;bung</translation>
    </message>
    <message>
        <source>&amp;Exploration: see the fundus, both ostia and every wall</source>
        <translation>&amp;Erkundung: den Fundus, beide Tubenostien und jede Wand sehen</translation>
    </message>
    <message>
        <source>&amp;Diagnosis: mark each pathology</source>
        <translation>&amp;Diagnose: jede Pathologie markieren</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;Keys...</source>
        <translation>&amp;Tasten...</translation>
    </message>
    <message>
        <source>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Arrow keys, or drag with the mouse&lt;/td&gt;&lt;td&gt;turn the scope about the cervix (pitch, yaw)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;W / S, or the mouse wheel&lt;/td&gt;&lt;td&gt;insert / withdraw&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Q / E&lt;/td&gt;&lt;td&gt;roll the scope (an oblique optic looks round)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Z / X&lt;/td&gt;&lt;td&gt;roll the camera head (the image&apos;s horizon)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;I / O&lt;/td&gt;&lt;td&gt;open or close the inflow / outflow valve&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Space&lt;/td&gt;&lt;td&gt;mark the pathology at the centre of the view&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Ctrl+E&lt;/td&gt;&lt;td&gt;end the trial and show the report&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Ctrl+R&lt;/td&gt;&lt;td&gt;restart the trial&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;F1&lt;/td&gt;&lt;td&gt;this help&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Pfeiltasten oder Ziehen mit der Maus&lt;/td&gt;&lt;td&gt;das Hysteroskop um die Zervix schwenken (auf/ab, links/rechts)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;W / S oder das Mausrad&lt;/td&gt;&lt;td&gt;einführen / zurückziehen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Q / E&lt;/td&gt;&lt;td&gt;das Hysteroskop drehen (eine Winkeloptik blickt zur Seite)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Z / X&lt;/td&gt;&lt;td&gt;den Kamerakopf drehen (den Horizont des Bildes)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;I / O&lt;/td&gt;&lt;td&gt;das Zulauf- / Ablaufventil öffnen oder schließen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Leertaste&lt;/td&gt;&lt;td&gt;die Pathologie in der Bildmitte markieren&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Ctrl+E&lt;/td&gt;&lt;td&gt;den Durchlauf beenden und den Bericht anzeigen&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Ctrl+R&lt;/td&gt;&lt;td&gt;den Durchlauf neu starten&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;F1&lt;/td&gt;&lt;td&gt;diese Hilfe&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
    <message>
        <source>Keys</source>
        <translation>Tasten</translation>
    </message>
    <message>
        <source>Loading %1...</source>
        <translation>%1 wird geladen...</translation>
    </message>
    <message>
        <source>The package could not be loaded.</source>
        <translation>Das Paket konnte nicht geladen werden.</translation>
    </message>
    <message>
        <source>Open Package</source>
        <translation>Paket öffnen</translation>
    </message>
    <message>
        <source>The scene package could not be loaded.</source>
        <translation>Das Szenenpaket konnte nicht geladen werden.</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>Wiedergabe</translation>
    </message>
    <message>
        <source>The trial could not be read.</source>
        <translation>Die Aufzeichnung des Durchlaufs konnte nicht gelesen werden.</translation>
    </message>
    <message>
        <source>Script</source>
        <translation>Skript</translation>
    </message>
    <message>
        <source>The script could not be read.</source>
        <translation>Das Skript konnte nicht gelesen werden.</translation>
    </message>
    <message>
        <source>Haptic device</source>
        <translation>Haptisches Gerät</translation>
    </message>
    <message>
        <source>The haptic hysteroscope could not be opened.</source>
        <translation>Das haptische Hysteroskop konnte nicht geöffnet werden.</translation>
    </message>
    <message>
        <source>hysteroscene simulator: %1</source>
        <translation>hysteroscene-Simulator: %1</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <source>The simulation stopped.</source>
        <translation>Die Simulation wurde abgebrochen.</translation>
    </message>
    <message>
        <source>The device&apos;s samples have ended: File &gt; End Trial shows the report.</source>
        <translation>Das Gerät liefert keine Abtastwerte mehr: Datei &gt; Durchlauf beenden zeigt den Bericht.</translation>
    </message>
    <message>
        <source>Save the Trial&apos;s Report</source>
        <translation>Bericht des Durchlaufs speichern</translation>
    </message>
    <message>
        <source>Trial reports (*.json)</source>
        <translation>Durchlaufberichte (*.json)</translation>
    </message>
    <message>
        <source>Trial Report</source>
        <translation>Bericht des Durchlaufs</translation>
    </message>
    <message>
        <source>The report is in %1. Open it?</source>
        <translation>Der Bericht liegt in %1. Öffnen?</translation>
    </message>
    <message>
        <source>The report could not be written.</source>
        <translation>Der Bericht konnte nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>Trial ended; report written to %1.</source>
        <translation>Durchlauf beendet; Bericht gespeichert unter %1.</translation>
    </message>
    <message>
        <source>Open a Scene Package</source>
        <translation>Szenenpaket öffnen</translation>
    </message>
    <message>
        <source> (light view: software GL)</source>
        <translation> (leichte Ansicht: Software-GL)</translation>
    </message>
    <message>
        <source>%L1 fps%4, physics %L2 steps/s, insertion %L3 mm</source>
        <translation>%L1 fps%4, Physik %L2 Schritte/s, Einführtiefe %L3 mm</translation>
    </message>
    <message>
        <source>The trial was recorded with other settings.</source>
        <translation>Der Versuch wurde mit anderen Einstellungen aufgezeichnet.</translation>
    </message>
    <message>
        <source>Demonstration</source>
        <translation>Demonstration</translation>
    </message>
    <message>
        <source>The demonstration could not be planned.</source>
        <translation>Die Demonstration konnte nicht geplant werden.</translation>
    </message>
</context>
<context>
    <name>hs::widgets</name>
    <message>
        <source>Gravidity counts every pregnancy, so it cannot be less than the parity.</source>
        <translation>Die Gravidität zählt jede Schwangerschaft und kann daher nicht kleiner als die Parität sein.</translation>
    </message>
    <message>
        <source>A postmenopausal patient is at least 40 years old, a premenopausal one at most 60.</source>
        <translation>Eine postmenopausale Patientin ist mindestens 40 Jahre alt, eine prämenopausale höchstens 60.</translation>
    </message>
    <message>
        <source>Only a premenopausal patient has a cycle phase.</source>
        <translation>Nur eine prämenopausale Patientin hat eine Zyklusphase.</translation>
    </message>
    <message>
        <source>The cavity must be shorter than the uterus.</source>
        <translation>Das Cavum muss kürzer sein als der Uterus.</translation>
    </message>
    <message>
        <source>The cavity must be narrower than the uterus.</source>
        <translation>Das Cavum muss schmaler sein als der Uterus.</translation>
    </message>
    <message>
        <source>Myomas are 5 – 100 mm, polyps 3 – 40 mm in size.</source>
        <translation>Myome sind 5 – 100 mm groß, Polypen 3 – 40 mm.</translation>
    </message>
    <message>
        <source>A case holds at most %1 pathologies.</source>
        <translation>Ein Fall enthält höchstens %1 Pathologien.</translation>
    </message>
    <message>
        <source>This value is not allowed here (%1).</source>
        <translation>Dieser Wert ist hier nicht zulässig (%1).</translation>
    </message>
    <message>
        <source>An id is 1 – 32 letters, digits, &apos;-&apos; or &apos;_&apos;, starts with a letter or digit, and is unique in the case.</source>
        <translation>Eine Kennung besteht aus 1 – 32 Buchstaben, Ziffern, &apos;-&apos; oder &apos;_&apos;, beginnt mit einem Buchstaben oder einer Ziffer und ist im Fall eindeutig.</translation>
    </message>
    <message>
        <source>Young&apos;s modulus must be in the range %1.</source>
        <translation>Der Elastizitätsmodul muss im Bereich %1 liegen.</translation>
    </message>
    <message>
        <source>The Poisson ratio must be in the range %1.</source>
        <translation>Die Poissonzahl muss im Bereich %1 liegen.</translation>
    </message>
    <message>
        <source>The density must be in the range %1.</source>
        <translation>Die Dichte muss im Bereich %1 liegen.</translation>
    </message>
    <message>
        <source>The heterogeneity must be in the range %1.</source>
        <translation>Die Heterogenität muss im Bereich %1 liegen.</translation>
    </message>
    <message>
        <source>The hydrometra pressure must be in the range %1.</source>
        <translation>Der Hydrometra-Druck muss im Bereich %1 liegen.</translation>
    </message>
    <message>
        <source>%1 must be in the range %2.</source>
        <translation>%1 muss im Bereich %2 liegen.</translation>
    </message>
</context>
<context>
    <name>hs::widgets::CaseDocument</name>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <source>Recover unsaved changes</source>
        <translation>Ungespeicherte Änderungen wiederherstellen</translation>
    </message>
    <message>
        <source>%1[*] - Hysteroscene</source>
        <translation>%1[*] - Hysteroscene</translation>
    </message>
</context>
<context>
    <name>hs::widgets::CaseEdits</name>
    <message>
        <source>Age</source>
        <translation>Alter</translation>
    </message>
    <message>
        <source>years</source>
        <translation>Jahre</translation>
    </message>
    <message>
        <source>Parity</source>
        <translation>Parität</translation>
    </message>
    <message>
        <source>births</source>
        <translation>Geburten</translation>
    </message>
    <message>
        <source>Gravidity</source>
        <translation>Gravidität</translation>
    </message>
    <message>
        <source>pregnancies</source>
        <translation>Schwangerschaften</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Körpergröße</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Gewicht</translation>
    </message>
    <message>
        <source>Uterine length</source>
        <translation>Uteruslänge</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Breite</translation>
    </message>
    <message>
        <source>AP depth</source>
        <translation>AP-Tiefe</translation>
    </message>
    <message>
        <source>Cavity length</source>
        <translation>Cavumlänge</translation>
    </message>
    <message>
        <source>Cavity width</source>
        <translation>Cavumbreite</translation>
    </message>
    <message>
        <source>Cervix length</source>
        <translation>Zervixlänge</translation>
    </message>
    <message>
        <source>Stalk length</source>
        <translation>Stiellänge</translation>
    </message>
    <message>
        <source>Target vertices</source>
        <translation>Zielanzahl Eckpunkte</translation>
    </message>
    <message>
        <source>Vessel density</source>
        <translation>Gefäßdichte</translation>
    </message>
    <message>
        <source>Fundal wall thickness</source>
        <translation>Dicke der Funduswand</translation>
    </message>
</context>
<context>
    <name>hs::widgets::ExportPanel</name>
    <message>
        <source>Scene package</source>
        <translation>Szenenpaket</translation>
    </message>
    <message>
        <source>Folder of the package</source>
        <translation>Ordner des Pakets</translation>
    </message>
    <message>
        <source>The package is written to this folder (created; an existing package is replaced)</source>
        <translation>Das Paket wird in diesen Ordner geschrieben (er wird angelegt; ein vorhandenes Paket wird ersetzt)</translation>
    </message>
    <message>
        <source>&amp;Browse...</source>
        <translation>&amp;Durchsuchen...</translation>
    </message>
    <message>
        <source>&amp;Folder</source>
        <translation>&amp;Ordner</translation>
    </message>
    <message>
        <source>Also as a .zip</source>
        <translation>Auch als .zip</translation>
    </message>
    <message>
        <source>Also the formats of other tools: glTF, Gmsh MSH, OBJ, SOFA</source>
        <translation>Auch die Formate anderer Werkzeuge: glTF, Gmsh MSH, OBJ, SOFA</translation>
    </message>
    <message>
        <source>More than one: a new patient of the same description per variant, each in folder/variant-NNN with its own seed</source>
        <translation>Mehr als eine: pro Variante eine neue Patientin mit derselben Beschreibung, jeweils in Ordner/variant-NNN mit eigenem Startwert</translation>
    </message>
    <message>
        <source>&amp;Variants</source>
        <translation>&amp;Varianten</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exportieren</translation>
    </message>
    <message>
        <source>Run what is not current, write the package and validate it (Ctrl+E)</source>
        <translation>Nicht aktuelle Schritte ausführen, das Paket schreiben und validieren (Ctrl+E)</translation>
    </message>
    <message>
        <source>Open in &amp;Simulator</source>
        <translation>Im &amp;Simulator öffnen</translation>
    </message>
    <message>
        <source>The preview simulator is not installed with this workstation</source>
        <translation>Der Vorschau-Simulator ist mit dieser Arbeitsstation nicht installiert</translation>
    </message>
    <message>
        <source>Start the preview simulator on the exported package</source>
        <translation>Den Vorschau-Simulator mit dem exportierten Paket starten</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;Choose a folder for the package first.&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;Zuerst einen Ordner für das Paket wählen.&lt;/span&gt;</translation>
    </message>
    <message>
        <source>Exporting...</source>
        <translation>Export läuft...</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: valid, %2 files with matching checksums (seed %3).</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;: gültig, %2 Dateien mit übereinstimmenden Prüfsummen (Startwert %3).</translation>
    </message>
    <message>
        <source>Zipped as %1.</source>
        <translation>Als %1 gezippt.</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;The simulator could not be started.&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;Der Simulator konnte nicht gestartet werden.&lt;/span&gt;</translation>
    </message>
    <message>
        <source>The scope&apos;s passage could not be checked: %1</source>
        <translation>Der Durchgang des Hysteroskops konnte nicht geprüft werden: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s), also in scene.json:</source>
        <translation>
            <numerusform>%n Warnung, auch in scene.json:</numerusform>
            <numerusform>%n Warnungen, auch in scene.json:</numerusform>
        </translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;A %1 mm scope does not pass the cervical canal (narrowest %2 mm).&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;Ein %1-mm-Hysteroskop passiert den Zervikalkanal nicht (engste Stelle %2 mm).&lt;/span&gt;</translation>
    </message>
    <message>
        <source>A %1 mm scope passes the cervical canal (narrowest %2 mm) and reaches the fundus (narrowest %3 mm).</source>
        <translation>Ein %1-mm-Hysteroskop passiert den Zervikalkanal (engste Stelle %2 mm) und erreicht den Fundus (engste Stelle %3 mm).</translation>
    </message>
    <message>
        <source>A %1 mm scope passes the cervical canal (narrowest %2 mm); a pathology narrows the way to the fundus to %3 mm.</source>
        <translation>Ein %1-mm-Hysteroskop passiert den Zervikalkanal (engste Stelle %2 mm); eine Pathologie verengt den Weg zum Fundus auf %3 mm.</translation>
    </message>
</context>
<context>
    <name>hs::widgets::GenerationSession</name>
    <message>
        <source>Building the organ</source>
        <translation>Organ wird aufgebaut</translation>
    </message>
    <message>
        <source>Growing the pathologies</source>
        <translation>Pathologien wachsen</translation>
    </message>
    <message>
        <source>Merging the body</source>
        <translation>Körper wird vereinigt</translation>
    </message>
    <message>
        <source>Meshing</source>
        <translation>Vernetzung</translation>
    </message>
    <message>
        <source>Texturing</source>
        <translation>Texturierung</translation>
    </message>
    <message>
        <source>Assembling the scene</source>
        <translation>Szene wird zusammengestellt</translation>
    </message>
    <message>
        <source>Exporting the scene</source>
        <translation>Szene wird exportiert</translation>
    </message>
</context>
<context>
    <name>hs::widgets::HysteroscopicPreview</name>
    <message>
        <source>How far the scope&apos;s tip is beyond the external os (mm)</source>
        <translation>Wie weit die Spitze des Hysteroskops über den äußeren Muttermund hinaus eingeführt ist (mm)</translation>
    </message>
    <message>
        <source>&amp;Insertion</source>
        <translation>&amp;Einführtiefe</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>The optic&apos;s angle off the shaft; office scopes are typically 30°</source>
        <translation>Winkel der Optik zur Schaftachse; Office-Hysteroskope haben meist 30°</translation>
    </message>
    <message>
        <source>&amp;Optic</source>
        <translation>&amp;Optik</translation>
    </message>
    <message>
        <source>The light post&apos;s rotation about the shaft (degrees; 0 looks anterior)</source>
        <translation>Drehung des Lichtleiteranschlusses um den Schaft (Grad; 0 blickt nach anterior)</translation>
    </message>
    <message>
        <source>&amp;Roll</source>
        <translation>&amp;Drehung</translation>
    </message>
    <message>
        <source>Texture the case to see the cavity.</source>
        <translation>Den Fall texturieren, um das Cavum zu sehen.</translation>
    </message>
    <message>
        <source>This scene has no cervical canal or ostium labels: the scope cannot be placed.</source>
        <translation>Diese Szene hat keine Markierungen für Zervikalkanal oder Muttermund: Das Hysteroskop kann nicht platziert werden.</translation>
    </message>
    <message>
        <source>Tip %1 mm beyond the external os, %2 optic, roll %3°</source>
        <translation>Spitze %1 mm hinter dem äußeren Muttermund, Optik %2, Drehung %3°</translation>
    </message>
    <message>
        <source>Looking at region %1 from %2 mm inside the cavity</source>
        <translation>Blick auf Region %1 aus %2 mm Abstand innerhalb des Cavums</translation>
    </message>
</context>
<context>
    <name>hs::widgets::JobRunner</name>
    <message>
        <source>The case asks for something the pipeline cannot make: a value is outside its allowed range or a pathology does not fit (see the details).</source>
        <translation>Der Fall verlangt etwas, das die Pipeline nicht erzeugen kann: Ein Wert liegt außerhalb seines zulässigen Bereichs oder eine Pathologie passt nicht hinein (siehe Details).</translation>
    </message>
    <message>
        <source>A file the case names does not exist.</source>
        <translation>Eine im Fall genannte Datei existiert nicht.</translation>
    </message>
    <message>
        <source>A file could not be read or written.</source>
        <translation>Eine Datei konnte nicht gelesen oder geschrieben werden.</translation>
    </message>
    <message>
        <source>The case asks for something this version does not support.</source>
        <translation>Der Fall verlangt etwas, das diese Version nicht unterstützt.</translation>
    </message>
    <message>
        <source>The result would be larger than this program accepts.</source>
        <translation>Das Ergebnis wäre größer, als dieses Programm zulässt.</translation>
    </message>
    <message>
        <source>The job was cancelled.</source>
        <translation>Der Auftrag wurde abgebrochen.</translation>
    </message>
    <message>
        <source>A geometry or image library failed on this case.</source>
        <translation>Eine Geometrie- oder Bildbibliothek ist bei diesem Fall fehlgeschlagen.</translation>
    </message>
    <message>
        <source>An internal error stopped the job.</source>
        <translation>Ein interner Fehler hat den Auftrag angehalten.</translation>
    </message>
</context>
<context>
    <name>hs::widgets::JobStatusWidget</name>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Stop the running job (Esc)</source>
        <translation>Den laufenden Auftrag abbrechen (Esc)</translation>
    </message>
    <message>
        <source>organ from the shape model</source>
        <translation>Organ aus dem Formmodell</translation>
    </message>
    <message>
        <source>pathologies</source>
        <translation>Pathologien</translation>
    </message>
    <message>
        <source>growing the pathologies</source>
        <translation>Pathologien wachsen</translation>
    </message>
    <message>
        <source>measuring the pathologies</source>
        <translation>Pathologien werden vermessen</translation>
    </message>
    <message>
        <source>merging</source>
        <translation>Vereinigung</translation>
    </message>
    <message>
        <source>joining the organ and the pathologies</source>
        <translation>Organ und Pathologien werden vereinigt</translation>
    </message>
    <message>
        <source>labelling the contacts</source>
        <translation>Kontakte werden markiert</translation>
    </message>
    <message>
        <source>covering the pathologies</source>
        <translation>Pathologien werden überzogen</translation>
    </message>
    <message>
        <source>checking the merged body</source>
        <translation>vereinigter Körper wird geprüft</translation>
    </message>
    <message>
        <source>meshing the body</source>
        <translation>Körper wird vernetzt</translation>
    </message>
    <message>
        <source>voxelizing the body</source>
        <translation>Körper wird voxelisiert</translation>
    </message>
    <message>
        <source>seeding the particles</source>
        <translation>Partikel werden gesetzt</translation>
    </message>
    <message>
        <source>relaxing the particles</source>
        <translation>Partikel werden relaxiert</translation>
    </message>
    <message>
        <source>tetrahedralizing</source>
        <translation>Tetraedrisierung</translation>
    </message>
    <message>
        <source>removing slivers</source>
        <translation>flache Tetraeder werden entfernt</translation>
    </message>
    <message>
        <source>checking the region volumes</source>
        <translation>Regionsvolumen werden geprüft</translation>
    </message>
    <message>
        <source>measuring the mesh quality</source>
        <translation>Netzqualität wird gemessen</translation>
    </message>
    <message>
        <source>mesh done</source>
        <translation>Netz fertig</translation>
    </message>
    <message>
        <source>tissue layers</source>
        <translation>Gewebeschichten</translation>
    </message>
    <message>
        <source>texturing</source>
        <translation>Texturierung</translation>
    </message>
    <message>
        <source>synthesizing the texture</source>
        <translation>Textur wird synthetisiert</translation>
    </message>
    <message>
        <source>growing the vessels</source>
        <translation>Gefäße wachsen</translation>
    </message>
    <message>
        <source>unfolding the surface</source>
        <translation>Oberfläche wird abgewickelt</translation>
    </message>
    <message>
        <source>baking the maps</source>
        <translation>Texturkarten werden gebacken</translation>
    </message>
    <message>
        <source>refining the surface for close-ups</source>
        <translation>Oberfläche wird für Nahaufnahmen verfeinert</translation>
    </message>
    <message>
        <source>binding the surface to the mesh</source>
        <translation>Oberfläche wird an das Netz gebunden</translation>
    </message>
    <message>
        <source>assembling the scene</source>
        <translation>Szene wird zusammengesetzt</translation>
    </message>
    <message>
        <source>distending the cavity</source>
        <translation>Cavum wird entfaltet</translation>
    </message>
    <message>
        <source>writing the package</source>
        <translation>Paket wird geschrieben</translation>
    </message>
    <message>
        <source>voxelizing the cavity for the scope</source>
        <translation>Cavum wird für das Hysteroskop voxelisiert</translation>
    </message>
    <message>
        <source>measuring the room for the scope</source>
        <translation>Platz für das Hysteroskop wird gemessen</translation>
    </message>
    <message>
        <source>sweeping the scope&apos;s route</source>
        <translation>Weg des Hysteroskops wird abgefahren</translation>
    </message>
    <message>
        <source>done</source>
        <translation>fertig</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>hs::widgets::MaterialsPanel</name>
    <message>
        <source>Myometrium</source>
        <translation>Myometrium</translation>
    </message>
    <message>
        <source>Endometrium</source>
        <translation>Endometrium</translation>
    </message>
    <message>
        <source>Cervix</source>
        <translation>Zervix</translation>
    </message>
    <message>
        <source>Myoma</source>
        <translation>Myom</translation>
    </message>
    <message>
        <source>Polyp</source>
        <translation>Polyp</translation>
    </message>
    <message>
        <source>Young&apos;s modulus (kPa)</source>
        <translation>Elastizitätsmodul (kPa)</translation>
    </message>
    <message>
        <source>Poisson ratio</source>
        <translation>Poissonzahl</translation>
    </message>
    <message>
        <source>Density (kg/m³)</source>
        <translation>Dichte (kg/m³)</translation>
    </message>
    <message>
        <source>Material</source>
        <translation>Material</translation>
    </message>
    <message>
        <source>Default material</source>
        <translation>Standardmaterial</translation>
    </message>
    <message>
        <source> kPa</source>
        <translation> kPa</translation>
    </message>
    <message>
        <source>Distension pressure the scene&apos;s hydrometra curve is computed for, %1 (8 kPa = 60 mmHg)</source>
        <translation>Distensionsdruck, für den die Hydrometra-Kurve der Szene berechnet wird, %1 (8 kPa = 60 mmHg)</translation>
    </message>
    <message>
        <source>&amp;Hydrometra pressure</source>
        <translation>&amp;Hydrometra-Druck</translation>
    </message>
    <message>
        <source>Hydrometra pressure</source>
        <translation>Hydrometra-Druck</translation>
    </message>
    <message>
        <source>Defaults: myometrium 30 kPa, endometrium 26.2 kPa (proliferative), myoma 65 kPa, polyp 15 kPa; Poisson ratio 0.47; 1050 kg/m³ (see docs/scene-format.md).</source>
        <translation>Standardwerte: Myometrium 30 kPa, Endometrium 26,2 kPa (Proliferationsphase), Myom 65 kPa, Polyp 15 kPa; Poissonzahl 0,47; 1050 kg/m³ (siehe docs/scene-format.md).</translation>
    </message>
    <message>
        <source>E (kPa)</source>
        <translation>E (kPa)</translation>
    </message>
    <message>
        <source>ν</source>
        <translation>ν</translation>
    </message>
    <message>
        <source>ρ (kg/m³)</source>
        <translation>ρ (kg/m³)</translation>
    </message>
    <message>
        <source>CV of E</source>
        <translation>VK von E</translation>
    </message>
    <message>
        <source>Heterogeneity: the coefficient of variation of Young&apos;s modulus per tetrahedron</source>
        <translation>Heterogenität: der Variationskoeffizient des Elastizitätsmoduls je Tetraeder</translation>
    </message>
    <message>
        <source>%1: default %2; allowed %3</source>
        <translation>%1: Standard %2; zulässig %3</translation>
    </message>
    <message>
        <source>Default: use the literature values for this tissue</source>
        <translation>Standard: die Literaturwerte für dieses Gewebe verwenden</translation>
    </message>
    <message>
        <source>Default values for %1</source>
        <translation>Standardwerte für %1</translation>
    </message>
</context>
<context>
    <name>hs::widgets::MeshPanel</name>
    <message>
        <source>tets</source>
        <translation>Tetraeder</translation>
    </message>
    <message>
        <source>Meshing</source>
        <translation>Vernetzung</translation>
    </message>
    <message>
        <source>Particles (Sierra et al. 2004)</source>
        <translation>Partikel (Sierra et al. 2004)</translation>
    </message>
    <message>
        <source>TetGen</source>
        <translation>TetGen</translation>
    </message>
    <message>
        <source>CGAL Mesh_3</source>
        <translation>CGAL Mesh_3</translation>
    </message>
    <message>
        <source>The particle mesher is the method of the paper; TetGen and CGAL are baselines</source>
        <translation>Der Partikel-Vernetzer ist das Verfahren der Publikation; TetGen und CGAL dienen als Vergleichsbasis</translation>
    </message>
    <message>
        <source>Vertices the mesh aims at: %1</source>
        <translation>Angestrebte Anzahl Eckpunkte des Netzes: %1</translation>
    </message>
    <message>
        <source>&amp;Target vertices</source>
        <translation>&amp;Zielanzahl Eckpunkte</translation>
    </message>
    <message>
        <source>Lattice</source>
        <translation>Gitter</translation>
    </message>
    <message>
        <source>Random, 2 per voxel</source>
        <translation>Zufällig, 2 pro Voxel</translation>
    </message>
    <message>
        <source>How particles are seeded inside the body (particle method)</source>
        <translation>Wie die Partikel anfangs im Körper verteilt werden (Partikelverfahren)</translation>
    </message>
    <message>
        <source>&amp;Seeding</source>
        <translation>&amp;Startverteilung</translation>
    </message>
    <message>
        <source>Most relaxation iterations (%1); relaxation also stops when it converges</source>
        <translation>Höchstzahl der Relaxationsiterationen (%1); die Relaxation endet auch, sobald sie konvergiert</translation>
    </message>
    <message>
        <source>&amp;Relaxation</source>
        <translation>&amp;Relaxation</translation>
    </message>
    <message>
        <source>&amp;Mesh</source>
        <translation>Ver&amp;netzen</translation>
    </message>
    <message>
        <source>Mesh the merged body and split the wall into its tissues (Ctrl+M)</source>
        <translation>Den vereinigten Körper vernetzen und die Wand in ihre Gewebe aufteilen (Ctrl+M)</translation>
    </message>
    <message>
        <source>Meshing method</source>
        <translation>Vernetzungsverfahren</translation>
    </message>
    <message>
        <source>Target vertices</source>
        <translation>Zielanzahl Eckpunkte</translation>
    </message>
    <message>
        <source>Seeding</source>
        <translation>Startverteilung</translation>
    </message>
    <message>
        <source>Relaxation iterations</source>
        <translation>Relaxationsiterationen</translation>
    </message>
    <message>
        <source>Quality</source>
        <translation>Qualität</translation>
    </message>
    <message>
        <source>Not meshed yet.</source>
        <translation>Noch nicht vernetzt.</translation>
    </message>
    <message>
        <source>Radius ratio</source>
        <translation>Radienverhältnis</translation>
    </message>
    <message>
        <source>3 × inradius / circumradius: 1 for the regular tetrahedron</source>
        <translation>3 × Inkugelradius / Umkugelradius: 1 für das reguläre Tetraeder</translation>
    </message>
    <message>
        <source>Smallest dihedral angle</source>
        <translation>Kleinster Diederwinkel</translation>
    </message>
    <message>
        <source>Degrees; below 10° a tet is a sliver</source>
        <translation>Grad; unter 10° ist ein Tetraeder ein Sliver (flaches Tetraeder)</translation>
    </message>
    <message>
        <source>Colour by</source>
        <translation>Einfärben nach</translation>
    </message>
    <message>
        <source>Tissue</source>
        <translation>Gewebe</translation>
    </message>
    <message>
        <source>Smallest dihedral</source>
        <translation>Kleinster Diederwinkel</translation>
    </message>
    <message>
        <source>Blue: poor, red: good (radius ratio 0 – 1, dihedral 0 – 70.5°)</source>
        <translation>Blau: schlecht, Rot: gut (Radienverhältnis 0 – 1, Diederwinkel 0 – 70,5°)</translation>
    </message>
    <message>
        <source>Regions shown</source>
        <translation>Angezeigte Regionen</translation>
    </message>
    <message>
        <source>Tet</source>
        <translation>Tetraeder</translation>
    </message>
    <message>
        <source>Region</source>
        <translation>Region</translation>
    </message>
    <message>
        <source>Dihedral</source>
        <translation>Diederwinkel</translation>
    </message>
    <message>
        <source>The worst tets by radius ratio; double-click or Show frames one in the view</source>
        <translation>Die schlechtesten Tetraeder nach Radienverhältnis; Doppelklick oder „Anzeigen“ holt eines in der Ansicht ins Bild</translation>
    </message>
    <message>
        <source>&amp;Show</source>
        <translation>&amp;Anzeigen</translation>
    </message>
    <message>
        <source>%1 vertices, %2 tets. Radius ratio: min %3, mean %4. Smallest dihedral %5°, %6 slivers. Boundary within %7 mm of the body; volume error %8 %.</source>
        <translation>%1 Eckpunkte, %2 Tetraeder. Radienverhältnis: min. %3, Mittel %4. Kleinster Diederwinkel %5°, %6 Sliver. Rand innerhalb von %7 mm zum Körper; Volumenfehler %8 %.</translation>
    </message>
    <message>
        <source>Inspecting the mesh</source>
        <translation>Netz wird untersucht</translation>
    </message>
    <message>
        <source>radius ratio</source>
        <translation>Radienverhältnis</translation>
    </message>
    <message>
        <source>Me&amp;thod</source>
        <translation>Me&amp;thode</translation>
    </message>
    <message>
        <source>smallest dihedral (°)</source>
        <translation>kleinster Diederwinkel (°)</translation>
    </message>
</context>
<context>
    <name>hs::widgets::PathologyPanel</name>
    <message>
        <source>0 – pedunculated, intracavitary</source>
        <translation>0 – gestielt, intrakavitär</translation>
    </message>
    <message>
        <source>1 – submucosal, &lt; 50 % intramural</source>
        <translation>1 – submukös, &lt; 50 % intramural</translation>
    </message>
    <message>
        <source>2 – submucosal, ≥ 50 % intramural</source>
        <translation>2 – submukös, ≥ 50 % intramural</translation>
    </message>
    <message>
        <source>3 – intramural, touching the endometrium</source>
        <translation>3 – intramural, mit Kontakt zum Endometrium</translation>
    </message>
    <message>
        <source>4 – intramural</source>
        <translation>4 – intramural</translation>
    </message>
    <message>
        <source>5 – subserosal, ≥ 50 % intramural</source>
        <translation>5 – subserös, ≥ 50 % intramural</translation>
    </message>
    <message>
        <source>6 – subserosal, &lt; 50 % intramural</source>
        <translation>6 – subserös, &lt; 50 % intramural</translation>
    </message>
    <message>
        <source>7 – subserosal, pedunculated</source>
        <translation>7 – subserös, gestielt</translation>
    </message>
    <message>
        <source>1-5 – hybrid, submucosal and subserosal</source>
        <translation>1-5 – hybrid, submukös und subserös</translation>
    </message>
    <message>
        <source>2-5 – hybrid, submucosal and subserosal</source>
        <translation>2-5 – hybrid, submukös und subserös</translation>
    </message>
    <message>
        <source>3-5 – hybrid, intramural and subserosal</source>
        <translation>3-5 – hybrid, intramural und subserös</translation>
    </message>
    <message>
        <source>Anterior wall</source>
        <translation>Vorderwand</translation>
    </message>
    <message>
        <source>Posterior wall</source>
        <translation>Hinterwand</translation>
    </message>
    <message>
        <source>Left lateral wall</source>
        <translation>Linke Seitenwand</translation>
    </message>
    <message>
        <source>Right lateral wall</source>
        <translation>Rechte Seitenwand</translation>
    </message>
    <message>
        <source>Left cornu</source>
        <translation>Linker Tubenwinkel</translation>
    </message>
    <message>
        <source>Right cornu</source>
        <translation>Rechter Tubenwinkel</translation>
    </message>
    <message>
        <source>Isthmus</source>
        <translation>Isthmus</translation>
    </message>
    <message>
        <source>Myoma</source>
        <translation>Myom</translation>
    </message>
    <message>
        <source>Polyp</source>
        <translation>Polyp</translation>
    </message>
    <message>
        <source>Add &amp;Myoma</source>
        <translation>&amp;Myom hinzufügen</translation>
    </message>
    <message>
        <source>Add a 20 mm FIGO 2 myoma at a free wall</source>
        <translation>Ein Myom FIGO 2 von 20 mm an einer freien Wand hinzufügen</translation>
    </message>
    <message>
        <source>Add &amp;Polyp</source>
        <translation>&amp;Polyp hinzufügen</translation>
    </message>
    <message>
        <source>Add a 10 mm sessile polyp at a free wall</source>
        <translation>Einen breitbasigen Polypen von 10 mm an einer freien Wand hinzufügen</translation>
    </message>
    <message>
        <source>D&amp;uplicate</source>
        <translation>&amp;Duplizieren</translation>
    </message>
    <message>
        <source>Copy the selected pathology to a free wall</source>
        <translation>Die ausgewählte Pathologie an eine freie Wand kopieren</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Entfernen</translation>
    </message>
    <message>
        <source>Selected pathology</source>
        <translation>Ausgewählte Pathologie</translation>
    </message>
    <message>
        <source>Names the pathology&apos;s region and files in the scene</source>
        <translation>Benennt die Region und die Dateien der Pathologie in der Szene</translation>
    </message>
    <message>
        <source>&amp;Id</source>
        <translation>&amp;ID</translation>
    </message>
    <message>
        <source>&amp;Kind</source>
        <translation>&amp;Art</translation>
    </message>
    <message>
        <source>Cellular automaton</source>
        <translation>Zellulärer Automat</translation>
    </message>
    <message>
        <source>Skeleton and contours</source>
        <translation>Skelett und Konturen</translation>
    </message>
    <message>
        <source>Particles</source>
        <translation>Partikel</translation>
    </message>
    <message>
        <source>How the pathology grows (Sierra et al. 2004); the automaton grows myomas only</source>
        <translation>Wie die Pathologie wächst (Sierra et al. 2004); der Automat lässt nur Myome wachsen</translation>
    </message>
    <message>
        <source>FIGO type: how deep the myoma sits in the wall (myomas only)</source>
        <translation>FIGO-Typ: wie tief das Myom in der Wand liegt (nur Myome)</translation>
    </message>
    <message>
        <source>&amp;FIGO type</source>
        <translation>&amp;FIGO-Typ</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Largest diameter in mm (a pedunculated polyp: of its head). Myomas 5 – 100 mm, polyps 3 – 40 mm</source>
        <translation>Größter Durchmesser in mm (bei einem gestielten Polypen: der des Kopfes). Myome 5 – 100 mm, Polypen 3 – 40 mm</translation>
    </message>
    <message>
        <source>Si&amp;ze</source>
        <translation>&amp;Größe</translation>
    </message>
    <message>
        <source>Sessile</source>
        <translation>Breitbasig</translation>
    </message>
    <message>
        <source>Pedunculated</source>
        <translation>Gestielt</translation>
    </message>
    <message>
        <source>&amp;Attachment</source>
        <translation>Ansat&amp;z</translation>
    </message>
    <message>
        <source>Stalk length in mm, %1 (pedunculated polyps)</source>
        <translation>Stiellänge in mm, %1 (gestielte Polypen)</translation>
    </message>
    <message>
        <source>S&amp;talk</source>
        <translation>S&amp;tiel</translation>
    </message>
    <message>
        <source>Placement</source>
        <translation>Platzierung</translation>
    </message>
    <message>
        <source>At a point</source>
        <translation>An einem Punkt</translation>
    </message>
    <message>
        <source>Click on Wall</source>
        <translation>Auf Wand klicken</translation>
    </message>
    <message>
        <source>Then click on the organ&apos;s wall in the 3-D view to seat the pathology there (Ctrl+P; Esc cancels)</source>
        <translation>Danach in der 3-D-Ansicht auf die Wand des Organs klicken, um die Pathologie dort zu platzieren (Ctrl+P; Esc bricht ab)</translation>
    </message>
    <message>
        <source>Grown</source>
        <translation>Wachstum</translation>
    </message>
    <message>
        <source>&amp;Grow</source>
        <translation>Wachsen &amp;lassen</translation>
    </message>
    <message>
        <source>Grow every pathology in the organ (Ctrl+G)</source>
        <translation>Alle Pathologien im Organ wachsen lassen (Ctrl+G)</translation>
    </message>
    <message>
        <source>M&amp;erge</source>
        <translation>&amp;Vereinigen</translation>
    </message>
    <message>
        <source>Merge the organ and the pathologies into one body with contact labels</source>
        <translation>Organ und Pathologien zu einem Körper mit Kontaktmarkierungen vereinigen</translation>
    </message>
    <message>
        <source>Pathology id</source>
        <translation>Pathologie-ID</translation>
    </message>
    <message>
        <source>Pathology kind</source>
        <translation>Art der Pathologie</translation>
    </message>
    <message>
        <source>Growth model</source>
        <translation>Wachstumsmodell</translation>
    </message>
    <message>
        <source>FIGO type</source>
        <translation>FIGO-Typ</translation>
    </message>
    <message>
        <source>Pathology size</source>
        <translation>Größe der Pathologie</translation>
    </message>
    <message>
        <source>Polyp attachment</source>
        <translation>Ansatz des Polypen</translation>
    </message>
    <message>
        <source>Stalk length</source>
        <translation>Stiellänge</translation>
    </message>
    <message>
        <source>The organ is still being built: click again once it is shown.</source>
        <translation>Das Organ wird noch aufgebaut: Erneut klicken, sobald es angezeigt wird.</translation>
    </message>
    <message>
        <source>Nothing placed: the click missed the organ. Click on its wall.</source>
        <translation>Nichts platziert: Der Klick hat das Organ verfehlt. Auf seine Wand klicken.</translation>
    </message>
    <message>
        <source>Nothing placed: that is the cervix, where pathologies are not modelled.</source>
        <translation>Nichts platziert: Das ist die Zervix, an der keine Pathologien modelliert werden.</translation>
    </message>
    <message>
        <source>Nothing placed: a polyp grows from the endometrium. Click on the cavity&apos;s wall (View &gt; Clip opens the organ).</source>
        <translation>Nichts platziert: Ein Polyp wächst aus dem Endometrium. Auf die Wand des Cavums klicken (Ansicht &gt; Schnitt öffnet das Organ).</translation>
    </message>
    <message>
        <source>Nothing placed: the click is not on the organ&apos;s wall.</source>
        <translation>Nichts platziert: Der Klick liegt nicht auf der Wand des Organs.</translation>
    </message>
    <message>
        <source>Place on wall</source>
        <translation>Auf der Wand platzieren</translation>
    </message>
    <message>
        <source>A case holds at most %1 pathologies.</source>
        <translation>Ein Fall enthält höchstens %1 Pathologien.</translation>
    </message>
    <message>
        <source>Add myoma</source>
        <translation>Myom hinzufügen</translation>
    </message>
    <message>
        <source>Add polyp</source>
        <translation>Polyp hinzufügen</translation>
    </message>
    <message>
        <source>Duplicate pathology</source>
        <translation>Pathologie duplizieren</translation>
    </message>
    <message>
        <source>Remove pathology</source>
        <translation>Pathologie entfernen</translation>
    </message>
    <message>
        <source>(%1, %2, %3) mm</source>
        <translation>(%1; %2; %3) mm</translation>
    </message>
    <message>
        <source>Not grown yet.</source>
        <translation>Noch nicht gewachsen.</translation>
    </message>
    <message>
        <source>Measured: FIGO &lt;b&gt;%1&lt;/b&gt;, %2 mm, %3 % in the wall, %4 % in the cavity</source>
        <translation>Gemessen: FIGO &lt;b&gt;%1&lt;/b&gt;, %2 mm, %3 % in der Wand, %4 % im Cavum</translation>
    </message>
    <message>
        <source>Lasmar score &lt;b&gt;%1&lt;/b&gt; (size %2, topography %3, extension %4, penetration %5, wall %6)</source>
        <translation>Lasmar-Score &lt;b&gt;%1&lt;/b&gt; (Größe %2, Topographie %3, Ausdehnung %4, Penetration %5, Wand %6)</translation>
    </message>
    <message>
        <source>Measured: a %1 mm head on a %2 mm stalk</source>
        <translation>Gemessen: Kopf von %1 mm an einem Stiel von %2 mm</translation>
    </message>
    <message>
        <source>Measured: sessile, %1 mm, base %2 mm</source>
        <translation>Gemessen: breitbasig, %1 mm, Basis %2 mm</translation>
    </message>
    <message>
        <source>From before the last edit: grow again.</source>
        <translation>Stand vor der letzten Änderung: Erneut wachsen lassen.</translation>
    </message>
    <message>
        <source>Fundus</source>
        <translation>Fundus</translation>
    </message>
    <message>
        <source>Gro&amp;wth model</source>
        <translation>&amp;Wachstumsmodell</translation>
    </message>
    <message>
        <source>Site</source>
        <translation>Lokalisation</translation>
    </message>
    <message>
        <source>measured FIGO %1</source>
        <translation>gemessen FIGO %1</translation>
    </message>
    <message>
        <source>On the final body: FIGO &lt;b&gt;%1&lt;/b&gt;</source>
        <translation>Am fertigen Körper: FIGO &lt;b&gt;%1&lt;/b&gt;</translation>
    </message>
    <message>
        <source>Requested FIGO %1, measured FIGO %2: the trainee meets another type than the case asks for.</source>
        <translation>Verlangt FIGO %1, gemessen FIGO %2: die Lernenden treffen einen anderen Typ an, als der Fall verlangt.</translation>
    </message>
    <message numerus="yes">
        <source>%n note(s) from the stage:</source>
        <translation>
            <numerusform>%n Hinweis der Stufe:</numerusform>
            <numerusform>%n Hinweise der Stufe:</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>hs::widgets::PatientPanel</name>
    <message>
        <source>Uterine length</source>
        <translation>Uteruslänge</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Breite</translation>
    </message>
    <message>
        <source>AP depth</source>
        <translation>AP-Tiefe</translation>
    </message>
    <message>
        <source>Cavity length</source>
        <translation>Cavumlänge</translation>
    </message>
    <message>
        <source>Cavity width</source>
        <translation>Cavumbreite</translation>
    </message>
    <message>
        <source>Cervix length</source>
        <translation>Zervixlänge</translation>
    </message>
    <message>
        <source>Patient</source>
        <translation>Patientin</translation>
    </message>
    <message>
        <source> years</source>
        <translation> Jahre</translation>
    </message>
    <message>
        <source>Age in years</source>
        <translation>Alter in Jahren</translation>
    </message>
    <message>
        <source>&amp;Age</source>
        <translation>&amp;Alter</translation>
    </message>
    <message>
        <source>years</source>
        <translation>Jahre</translation>
    </message>
    <message>
        <source>Births after 20 weeks of gestation</source>
        <translation>Geburten nach der 20. Schwangerschaftswoche</translation>
    </message>
    <message>
        <source>&amp;Parity</source>
        <translation>&amp;Parität</translation>
    </message>
    <message>
        <source>births</source>
        <translation>Geburten</translation>
    </message>
    <message>
        <source>Pregnancies, including those that ended in a birth (at least the parity)</source>
        <translation>Schwangerschaften, einschließlich derer, die mit einer Geburt endeten (mindestens die Parität)</translation>
    </message>
    <message>
        <source>&amp;Gravidity</source>
        <translation>&amp;Gravidität</translation>
    </message>
    <message>
        <source>pregnancies</source>
        <translation>Schwangerschaften</translation>
    </message>
    <message>
        <source> cm</source>
        <translation> cm</translation>
    </message>
    <message>
        <source>Height in centimetres</source>
        <translation>Körpergröße in Zentimetern</translation>
    </message>
    <message>
        <source>&amp;Height</source>
        <translation>&amp;Körpergröße</translation>
    </message>
    <message>
        <source>cm</source>
        <translation>cm</translation>
    </message>
    <message>
        <source> kg</source>
        <translation> kg</translation>
    </message>
    <message>
        <source>Weight in kilograms</source>
        <translation>Gewicht in Kilogramm</translation>
    </message>
    <message>
        <source>&amp;Weight</source>
        <translation>Ge&amp;wicht</translation>
    </message>
    <message>
        <source>kg</source>
        <translation>kg</translation>
    </message>
    <message>
        <source>Postmenopausal</source>
        <translation>Postmenopausal</translation>
    </message>
    <message>
        <source>Postmenopausal patients are 40 years or older; premenopausal ones at most 60</source>
        <translation>Postmenopausale Patientinnen sind 40 Jahre oder älter, prämenopausale höchstens 60</translation>
    </message>
    <message>
        <source>Menstrual</source>
        <translation>Menstruationsphase</translation>
    </message>
    <message>
        <source>Proliferative</source>
        <translation>Proliferationsphase</translation>
    </message>
    <message>
        <source>Secretory</source>
        <translation>Sekretionsphase</translation>
    </message>
    <message>
        <source>Phase of the cycle on the day of the hysteroscopy; it sets the endometrium&apos;s thickness (premenopausal patients only)</source>
        <translation>Zyklusphase am Tag der Hysteroskopie; sie bestimmt die Dicke des Endometriums (nur prämenopausale Patientinnen)</translation>
    </message>
    <message>
        <source>C&amp;ycle phase</source>
        <translation>&amp;Zyklusphase</translation>
    </message>
    <message>
        <source>Sample for this patient</source>
        <translation>Stichprobe für diese Patientin</translation>
    </message>
    <message>
        <source>Mean for this patient</source>
        <translation>Mittelwert für diese Patientin</translation>
    </message>
    <message>
        <source>A seeded organ of the statistical shape model, or the model&apos;s mean for the patient</source>
        <translation>Ein aus dem Startwert erzeugtes Organ des statistischen Formmodells oder der Mittelwert des Modells für die Patientin</translation>
    </message>
    <message>
        <source>&amp;Organ</source>
        <translation>&amp;Organ</translation>
    </message>
    <message>
        <source>Every random choice of every stage derives from the seed: the same seed gives the same scene</source>
        <translation>Jede Zufallsentscheidung jeder Stufe leitet sich vom Startwert ab: Derselbe Startwert ergibt dieselbe Szene</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Neu</translation>
    </message>
    <message>
        <source>Draw a new seed: a new patient of the same description</source>
        <translation>Einen neuen Startwert ziehen: eine neue Patientin mit derselben Beschreibung</translation>
    </message>
    <message>
        <source>&amp;Seed</source>
        <translation>&amp;Startwert</translation>
    </message>
    <message>
        <source>Dimensions</source>
        <translation>Maße</translation>
    </message>
    <message>
        <source>Set a dimension to a measured value (ultrasound) and the organ is fitted to it</source>
        <translation>Ein Maß auf einen gemessenen Wert (Ultraschall) setzen; das Organ wird daran angepasst</translation>
    </message>
    <message>
        <source>This organ</source>
        <translation>Dieses Organ</translation>
    </message>
    <message>
        <source>Expected (95 %)</source>
        <translation>Erwartet (95 %)</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>Gemessen</translation>
    </message>
    <message>
        <source>The published relations for this patient, mean ± 1.96 SD</source>
        <translation>Die publizierten Zusammenhänge für diese Patientin, Mittelwert ± 1,96 SD</translation>
    </message>
    <message>
        <source>Fit the organ to a measured value</source>
        <translation>Organ an einen gemessenen Wert anpassen</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Allowed: %1</source>
        <translation>Zulässig: %1</translation>
    </message>
    <message>
        <source>Age</source>
        <translation>Alter</translation>
    </message>
    <message>
        <source>Parity</source>
        <translation>Parität</translation>
    </message>
    <message>
        <source>Gravidity</source>
        <translation>Gravidität</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Körpergröße</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Gewicht</translation>
    </message>
    <message>
        <source>Menopausal state</source>
        <translation>Menopausenstatus</translation>
    </message>
    <message>
        <source>Cycle phase</source>
        <translation>Zyklusphase</translation>
    </message>
    <message>
        <source>Organ mode</source>
        <translation>Organmodus</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Startwert</translation>
    </message>
    <message>
        <source>New seed</source>
        <translation>Neuer Startwert</translation>
    </message>
    <message>
        <source>%1 – %2 mm</source>
        <translation>%1 – %2 mm</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>Outside the expected range for this patient</source>
        <translation>Außerhalb des erwarteten Bereichs für diese Patientin</translation>
    </message>
    <message>
        <source>Fundal wall thickness</source>
        <translation>Dicke der Funduswand</translation>
    </message>
    <message>
        <source>(outside)</source>
        <translation>(außerhalb)</translation>
    </message>
</context>
<context>
    <name>hs::widgets::ReviewPanel</name>
    <message>
        <source>cellular automaton</source>
        <translation>zellulärer Automat</translation>
    </message>
    <message>
        <source>skeleton</source>
        <translation>Skelett</translation>
    </message>
    <message>
        <source>particles</source>
        <translation>Partikel</translation>
    </message>
    <message>
        <source>–</source>
        <translation>–</translation>
    </message>
    <message>
        <source>1: not realistic … 5: indistinguishable from a real one; – not rated</source>
        <translation>1: nicht realistisch … 5: von einem echten nicht zu unterscheiden; – nicht bewertet</translation>
    </message>
    <message>
        <source>No package opened for review (File &gt; Review Scene Package).</source>
        <translation>Kein Paket zur Begutachtung geöffnet (Datei &gt; Szenenpaket begutachten).</translation>
    </message>
    <message>
        <source>Reviewer</source>
        <translation>Gutachter/in</translation>
    </message>
    <message>
        <source>Pathologies</source>
        <translation>Pathologien</translation>
    </message>
    <message>
        <source>Id</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>Growth</source>
        <translation>Wachstum</translation>
    </message>
    <message>
        <source>Realism</source>
        <translation>Realismus</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Kommentar</translation>
    </message>
    <message>
        <source>Textures</source>
        <translation>Texturen</translation>
    </message>
    <message>
        <source>Appearance</source>
        <translation>Erscheinungsbild</translation>
    </message>
    <message>
        <source>Save &amp;Review</source>
        <translation>Begutachtung &amp;speichern</translation>
    </message>
    <message>
        <source>Write the ratings beside the package (the package itself is not changed)</source>
        <translation>Die Bewertungen neben das Paket schreiben (das Paket selbst wird nicht verändert)</translation>
    </message>
    <message>
        <source>All reviews in this folder</source>
        <translation>Alle Begutachtungen in diesem Ordner</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Gruppe</translation>
    </message>
    <message>
        <source>Ratings</source>
        <translation>Bewertungen</translation>
    </message>
    <message>
        <source>Mean</source>
        <translation>Mittelwert</translation>
    </message>
    <message>
        <source>Lowest</source>
        <translation>Minimum</translation>
    </message>
    <message>
        <source>Highest</source>
        <translation>Maximum</translation>
    </message>
    <message>
        <source>Reviewing %1 (read-only)</source>
        <translation>Begutachtung von %1 (schreibgeschützt)</translation>
    </message>
    <message>
        <source>myoma</source>
        <translation>Myom</translation>
    </message>
    <message>
        <source>polyp</source>
        <translation>Polyp</translation>
    </message>
    <message>
        <source>Visit</source>
        <translation>Ansehen</translation>
    </message>
    <message>
        <source>Look at this pathology from inside the cavity</source>
        <translation>Diese Pathologie aus dem Inneren des Cavums betrachten</translation>
    </message>
    <message>
        <source>The pathology %1 is not a region of this scene.</source>
        <translation>Die Pathologie %1 ist keine Region dieser Szene.</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;The review could not be written beside the package (is the folder read-only?).&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;Die Begutachtung konnte nicht neben das Paket geschrieben werden (ist der Ordner schreibgeschützt?).&lt;/span&gt;</translation>
    </message>
    <message>
        <source>Saved to %1.</source>
        <translation>Gespeichert unter %1.</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;The review %1 is of another package (manifest SHA-256 %2…, this package&apos;s %3…): it is not loaded. Saving keeps it as %4.&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;Die Bewertung %1 gehört zu einem anderen Paket (Manifest-SHA-256 %2…, dieses Pakets %3…): Sie wird nicht geladen. Beim Speichern bleibt sie als %4 erhalten.&lt;/span&gt;</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;The review %1 cannot be read: it is not loaded. Saving keeps it as %2.&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;Die Bewertung %1 ist nicht lesbar: Sie wird nicht geladen. Beim Speichern bleibt sie als %2 erhalten.&lt;/span&gt;</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;The review of another package, %1, could not be moved to %2: nothing was saved.&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;Die Bewertung eines anderen Pakets, %1, konnte nicht nach %2 verschoben werden: Nichts wurde gespeichert.&lt;/span&gt;</translation>
    </message>
    <message>
        <source>endometrium</source>
        <translation>Endometrium</translation>
    </message>
    <message>
        <source>texture / %1</source>
        <translation>Textur / %1</translation>
    </message>
    <message>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
</context>
<context>
    <name>hs::widgets::SceneTree</name>
    <message>
        <source>Organ (shape model)</source>
        <translation>Organ (Formmodell)</translation>
    </message>
    <message>
        <source>Growth</source>
        <translation>Wachstum</translation>
    </message>
    <message>
        <source>Displaced organ</source>
        <translation>Verdrängtes Organ</translation>
    </message>
    <message>
        <source>%1 (grown)</source>
        <translation>%1 (gewachsen)</translation>
    </message>
    <message>
        <source>Merged body</source>
        <translation>Vereinigter Körper</translation>
    </message>
    <message>
        <source>Wall</source>
        <translation>Wand</translation>
    </message>
    <message>
        <source>%1 (merged)</source>
        <translation>%1 (vereinigt)</translation>
    </message>
    <message>
        <source>Tetrahedral mesh</source>
        <translation>Tetraedernetz</translation>
    </message>
    <message>
        <source>Visual surface (textured)</source>
        <translation>Sichtbare Oberfläche (texturiert)</translation>
    </message>
    <message>
        <source>Simulation mesh</source>
        <translation>Simulationsnetz</translation>
    </message>
    <message>
        <source>Part</source>
        <translation>Teil</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation>Deckkraft</translation>
    </message>
    <message>
        <source>What the 3-D view shows: tick a part to show it, set its opacity to see inside it</source>
        <translation>Was die 3-D-Ansicht zeigt: ein Teil abhaken, um es zu zeigen, seine Deckkraft senken, um hineinzusehen</translation>
    </message>
    <message>
        <source>Opacity of %1: lower it to see the parts inside</source>
        <translation>Deckkraft von %1: senken, um die Teile darin zu sehen</translation>
    </message>
    <message>
        <source>Opacity of %1</source>
        <translation>Deckkraft von %1</translation>
    </message>
    <message>
        <source>%1 — out of date</source>
        <translation>%1 — veraltet</translation>
    </message>
    <message>
        <source>The case has changed since this stage ran: what it shows is not the case as it is now, until the stage reruns</source>
        <translation>Der Fall wurde geändert, seit dieser Schritt lief: Was er zeigt, ist nicht der Fall, wie er jetzt ist, bis der Schritt erneut läuft</translation>
    </message>
</context>
<context>
    <name>hs::widgets::SceneWarnings</name>
    <message>
        <source>The texture stage substituted or left out part of the look: the surface may not look as the case describes.</source>
        <translation>Die Texturstufe hat einen Teil des Aussehens ersetzt oder weggelassen: die Oberfläche sieht womöglich nicht aus, wie der Fall es beschreibt.</translation>
    </message>
    <message>
        <source>A pathology could not be placed or grown exactly as asked (moved off a tubal ostium or another pathology, or grown to another size or type): look at it in the 3-D view.</source>
        <translation>Eine Pathologie konnte nicht genau wie verlangt platziert oder gezüchtet werden (von einem Tubenostium oder einer anderen Pathologie weggerückt, oder in anderer Größe oder anderem Typ gewachsen): in der 3-D-Ansicht ansehen.</translation>
    </message>
    <message>
        <source>Joining the pathologies to the organ changed or dropped part of one: check where they meet.</source>
        <translation>Beim Verbinden der Pathologien mit dem Organ wurde ein Teil einer Pathologie verändert oder entfernt: die Berührungsstellen prüfen.</translation>
    </message>
    <message>
        <source>The mesher repaired or approximated part of the body: the mesh may differ from the shape it was made from.</source>
        <translation>Der Vernetzer hat einen Teil des Körpers repariert oder angenähert: das Netz kann von der Form abweichen, aus der es entstand.</translation>
    </message>
    <message>
        <source>A measured FIGO type, Lasmar score or size differs from the one the case asks for: the trainee meets another grade than intended.</source>
        <translation>Ein gemessener FIGO-Typ, Lasmar-Score oder eine Größe weicht von der Vorgabe des Falls ab: die Lernenden treffen einen anderen Grad an als beabsichtigt.</translation>
    </message>
    <message>
        <source>A clinical measurement fell back to an approximation: the reported figures are less certain.</source>
        <translation>Eine klinische Messung musste auf eine Näherung ausweichen: die berichteten Werte sind unsicherer.</translation>
    </message>
    <message>
        <source>A polyp lies against the wall over more of its surface than its kind allows: it may look buried in the wall rather than standing in the cavity.</source>
        <translation>Ein Polyp liegt mit mehr Oberfläche an der Wand, als seine Art erlaubt: er wirkt womöglich in der Wand vergraben statt im Cavum stehend.</translation>
    </message>
    <message>
        <source>The cavity&apos;s opening under the distension pressure was estimated from the organ without its pathologies: distension in the simulator is approximate.</source>
        <translation>Die Öffnung des Cavums unter dem Distensionsdruck wurde am Organ ohne seine Pathologien geschätzt: die Distension im Simulator ist genähert.</translation>
    </message>
    <message>
        <source>Part of the visible surface is bound away from the simulation mesh: it may drift off the tissue when the tissue moves.</source>
        <translation>Ein Teil der sichtbaren Oberfläche ist abseits des Simulationsnetzes gebunden: er kann sich vom Gewebe lösen, wenn sich das Gewebe bewegt.</translation>
    </message>
    <message>
        <source>The tetrahedral mesh misses one of its quality bars: the simulation may be less accurate or less stable where the bad elements are.</source>
        <translation>Das Tetraedernetz verfehlt eine seiner Qualitätsschwellen: die Simulation kann dort, wo die schlechten Elemente liegen, ungenauer oder weniger stabil sein.</translation>
    </message>
    <message>
        <source>See the scene package&apos;s documentation (docs/scene-format.md) for this warning.</source>
        <translation>Zu dieser Warnung siehe die Dokumentation des Szenenpakets (docs/scene-format.md).</translation>
    </message>
</context>
<context>
    <name>hs::widgets::TexturePanel</name>
    <message>
        <source>Endometrium</source>
        <translation>Endometrium</translation>
    </message>
    <message>
        <source>Myoma</source>
        <translation>Myom</translation>
    </message>
    <message>
        <source>Polyp</source>
        <translation>Polyp</translation>
    </message>
    <message>
        <source>Texture</source>
        <translation>Textur</translation>
    </message>
    <message>
        <source>%1 × %1 px</source>
        <translation>%1 × %1 px</translation>
    </message>
    <message>
        <source>Side of each square map in pixels</source>
        <translation>Seitenlänge jeder quadratischen Karte in Pixeln</translation>
    </message>
    <message>
        <source>Map &amp;size</source>
        <translation>&amp;Kartengröße</translation>
    </message>
    <message>
        <source>Vessels relative to the default network, %1; 0: none</source>
        <translation>Gefäße relativ zum Standard-Gefäßnetz, %1; 0: keine</translation>
    </message>
    <message>
        <source>&amp;Vessel density</source>
        <translation>&amp;Gefäßdichte</translation>
    </message>
    <message>
        <source>Choose...</source>
        <translation>Auswählen...</translation>
    </message>
    <message>
        <source>Bundled</source>
        <translation>Mitgeliefert</translation>
    </message>
    <message>
        <source>Use the bundled procedural exemplar</source>
        <translation>Die mitgelieferte prozedurale Vorlage verwenden</translation>
    </message>
    <message>
        <source>Bundled exemplar</source>
        <translation>Mitgelieferte Vorlage</translation>
    </message>
    <message>
        <source>&amp;Texture</source>
        <translation>&amp;Texturieren</translation>
    </message>
    <message>
        <source>Synthesize and bake the maps on the final surface (Ctrl+T)</source>
        <translation>Die Karten synthetisieren und auf die endgültige Oberfläche backen (Ctrl+T)</translation>
    </message>
    <message>
        <source>Maps</source>
        <translation>Karten</translation>
    </message>
    <message>
        <source>Albedo</source>
        <translation>Albedo</translation>
    </message>
    <message>
        <source>Normal</source>
        <translation>Normalen</translation>
    </message>
    <message>
        <source>Roughness</source>
        <translation>Rauheit</translation>
    </message>
    <message>
        <source>Zoom in</source>
        <translation>Vergrößern</translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation>Verkleinern</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Einpassen</translation>
    </message>
    <message>
        <source>Map size</source>
        <translation>Kartengröße</translation>
    </message>
    <message>
        <source>Vessel density</source>
        <translation>Gefäßdichte</translation>
    </message>
    <message>
        <source>The file %1 does not exist.</source>
        <translation>Die Datei %1 existiert nicht.</translation>
    </message>
    <message>
        <source>The image %1 is too small or too large: each side must be %2 – %3 px.</source>
        <translation>Das Bild %1 ist zu klein oder zu groß: Jede Seite muss %2 – %3 px lang sein.</translation>
    </message>
    <message>
        <source>The file %1 is not an image this program reads (PNG, JPEG, EXR, TIFF).</source>
        <translation>Die Datei %1 ist kein Bild, das dieses Programm lesen kann (PNG, JPEG, EXR, TIFF).</translation>
    </message>
    <message>
        <source>Exemplar image</source>
        <translation>Vorlagenbild</translation>
    </message>
    <message>
        <source>The bundled procedural exemplar</source>
        <translation>Die mitgelieferte prozedurale Vorlage</translation>
    </message>
    <message>
        <source>Use your own image (PNG, JPEG, EXR, TIFF; %1 – %2 px a side): a crop of a real hysteroscopic view</source>
        <translation>Eigenes Bild verwenden (PNG, JPEG, EXR, TIFF; %1 – %2 px je Seite): ein Ausschnitt eines echten hysteroskopischen Bildes</translation>
    </message>
    <message>
        <source>Cervical canal</source>
        <translation>Zervixkanal</translation>
    </message>
</context>
<context>
    <name>hs::widgets::TrialReportView</name>
    <message>
        <source>%1 min %2 s</source>
        <translation>%1 min %2 s</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Exploration</source>
        <translation>Erkundung</translation>
    </message>
    <message>
        <source>Diagnosis</source>
        <translation>Diagnose</translation>
    </message>
    <message>
        <source>Polypectomy</source>
        <translation>Polypektomie</translation>
    </message>
    <message>
        <source>Myomectomy</source>
        <translation>Myomektomie</translation>
    </message>
    <message>
        <source>&amp;Metrics</source>
        <translation>&amp;Messwerte</translation>
    </message>
    <message>
        <source>&amp;Over Time</source>
        <translation>&amp;Zeitverlauf</translation>
    </message>
    <message>
        <source>&amp;Visualized Surface</source>
        <translation>&amp;Gesehene Oberfläche</translation>
    </message>
    <message>
        <source>%1 trial, %2</source>
        <translation>Durchlauf %1, %2</translation>
    </message>
    <message>
        <source>Scene %1, seed %2, %3° optic, %4 mm scope; device %5; physics %6.</source>
        <translation>Szene %1, Startwert %2, %3°-Optik, %4-mm-Hysteroskop; Gerät %5; Physik %6.</translation>
    </message>
    <message>
        <source>Started %1 (UTC).</source>
        <translation>Begonnen %1 (UTC).</translation>
    </message>
    <message>
        <source>Report: %1</source>
        <translation>Bericht: %1</translation>
    </message>
    <message>
        <source>Open the trial&apos;s scene package for review (File &gt; Review Scene Package) to see its organ beside the report.</source>
        <translation>Öffnen Sie das Szenenpaket des Durchlaufs zur Begutachtung (Datei &gt; Szenenpaket begutachten), um sein Organ neben dem Bericht zu sehen.</translation>
    </message>
    <message>
        <source>This trial ran on the scene under review.</source>
        <translation>Dieser Durchlauf lief auf der begutachteten Szene.</translation>
    </message>
    <message>
        <source>This trial ran on another scene than the one under review (%1, not %2).</source>
        <translation>Dieser Durchlauf lief auf einer anderen Szene als der begutachteten (%1, nicht %2).</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>Cavity surface, unrolled about the canal&apos;s axis</source>
        <translation>Oberfläche des Cavums, um die Achse des Kanals abgerollt</translation>
    </message>
    <message>
        <source>seen</source>
        <translation>gesehen</translation>
    </message>
    <message>
        <source>not seen</source>
        <translation>nicht gesehen</translation>
    </message>
    <message>
        <source>around the axis (degrees; 0 anterior, +90 the patient&apos;s left)</source>
        <translation>um die Achse (Grad; 0 anterior, +90 links der Patientin)</translation>
    </message>
    <message>
        <source>from the internal os (mm)</source>
        <translation>vom inneren Muttermund (mm)</translation>
    </message>
    <message>
        <source>&amp;Replay in the Simulator...</source>
        <translation>Im Simulator &amp;wiedergeben...</translation>
    </message>
    <message>
        <source>Play the recorded trial again in the simulator, on its scene package.</source>
        <translation>Den aufgezeichneten Durchlauf im Simulator erneut abspielen, auf seinem Szenenpaket.</translation>
    </message>
    <message>
        <source>No recorded trial (%1.trial) beside the report: the simulator writes one with the report when a trial ends.</source>
        <translation>Kein aufgezeichneter Durchlauf (%1.trial) neben dem Bericht: der Simulator schreibt ihn mit dem Bericht, wenn ein Durchlauf endet.</translation>
    </message>
</context>
<context>
    <name>hs::widgets::VariantsView</name>
    <message>
        <source>How far every scope&apos;s tip is beyond its external os (mm)</source>
        <translation>Wie weit die Spitze jedes Hysteroskops hinter dem äußeren Muttermund liegt (mm)</translation>
    </message>
    <message>
        <source>&amp;Insertion</source>
        <translation>&amp;Einführtiefe</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>&amp;Optic</source>
        <translation>&amp;Optik</translation>
    </message>
    <message>
        <source>&amp;Roll</source>
        <translation>&amp;Drehung</translation>
    </message>
</context>
<context>
    <name>hs::workstation::MainWindow</name>
    <message>
        <source>&amp;Open...</source>
        <translation>Ö&amp;ffnen...</translation>
    </message>
    <message>
        <source>Open a surface or tetrahedral mesh</source>
        <translation>Eine Oberfläche oder ein Tetraedernetz öffnen</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Clear Menu</source>
        <translation>Menü &amp;leeren</translation>
    </message>
    <message>
        <source>&amp;Clip</source>
        <translation>&amp;Schnitt</translation>
    </message>
    <message>
        <source>Cut the tetrahedral mesh open and show the tetrahedra on the cut</source>
        <translation>Das Tetraedernetz aufschneiden und die Tetraeder an der Schnittfläche zeigen</translation>
    </message>
    <message>
        <source>&amp;Reset Camera</source>
        <translation>Kamera &amp;zurücksetzen</translation>
    </message>
    <message>
        <source>&amp;About Hysteroscene</source>
        <translation>Ü&amp;ber Hysteroscene</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>All meshes (%1)</source>
        <translation>Alle Netze (%1)</translation>
    </message>
    <message>
        <source>Surface meshes (%1)</source>
        <translation>Oberflächennetze (%1)</translation>
    </message>
    <message>
        <source>Tetrahedral meshes (%1)</source>
        <translation>Tetraedernetze (%1)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Open Mesh</source>
        <translation>Netz öffnen</translation>
    </message>
    <message>
        <source>Opening %1...</source>
        <translation>%1 wird geöffnet...</translation>
    </message>
    <message>
        <source>The file %1 does not exist.</source>
        <translation>Die Datei %1 existiert nicht.</translation>
    </message>
    <message>
        <source>The file %1 could not be read.</source>
        <translation>Die Datei %1 konnte nicht gelesen werden.</translation>
    </message>
    <message>
        <source>The file %1 is in a format or version this program does not read.</source>
        <translation>Die Datei %1 liegt in einem Format oder einer Version vor, die dieses Programm nicht lesen kann.</translation>
    </message>
    <message>
        <source>The file %1 is larger than this program accepts.</source>
        <translation>Die Datei %1 ist größer, als dieses Programm zulässt.</translation>
    </message>
    <message>
        <source>The file %1 is not a valid mesh.</source>
        <translation>Die Datei %1 ist kein gültiges Netz.</translation>
    </message>
    <message>
        <source>The file %1 could not be opened.</source>
        <translation>Die Datei %1 konnte nicht geöffnet werden.</translation>
    </message>
    <message>
        <source>Nothing picked</source>
        <translation>Nichts ausgewählt</translation>
    </message>
    <message>
        <source>Picked (%1, %2, %3) mm</source>
        <translation>Gewählter Punkt (%1; %2; %3) mm</translation>
    </message>
    <message>
        <source>No mesh</source>
        <translation>Kein Netz</translation>
    </message>
    <message>
        <source>Vertices: %1   Tetrahedra: %2   Regions: %3</source>
        <translation>Eckpunkte: %1   Tetraeder: %2   Regionen: %3</translation>
    </message>
    <message>
        <source>Shown: %1</source>
        <translation>Angezeigt: %1</translation>
    </message>
    <message>
        <source>Vertices: %1   Triangles: %2   Regions: %3</source>
        <translation>Eckpunkte: %1   Dreiecke: %2   Regionen: %3</translation>
    </message>
    <message>
        <source>About Hysteroscene</source>
        <translation>Über Hysteroscene</translation>
    </message>
    <message>
        <source>&amp;New Case</source>
        <translation>&amp;Neuer Fall</translation>
    </message>
    <message>
        <source>Start a new case from the default patient</source>
        <translation>Einen neuen Fall mit der Standardpatientin beginnen</translation>
    </message>
    <message>
        <source>Open &amp;Case...</source>
        <translation>&amp;Fall öffnen...</translation>
    </message>
    <message>
        <source>Open a case file (case.json)</source>
        <translation>Eine Falldatei öffnen (case.json)</translation>
    </message>
    <message>
        <source>&amp;Save Case</source>
        <translation>Fall &amp;speichern</translation>
    </message>
    <message>
        <source>Save Case &amp;As...</source>
        <translation>Fall speichern &amp;unter...</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>The case %1 has unsaved changes. Save them?</source>
        <translation>Der Fall %1 hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
    <message>
        <source>The case file does not exist.</source>
        <translation>Die Falldatei existiert nicht.</translation>
    </message>
    <message>
        <source>The case file could not be read or written.</source>
        <translation>Die Falldatei konnte nicht gelesen oder geschrieben werden.</translation>
    </message>
    <message>
        <source>The case file is of a version this program does not read.</source>
        <translation>Die Falldatei hat eine Version, die dieses Programm nicht lesen kann.</translation>
    </message>
    <message>
        <source>The case file is larger than this program accepts.</source>
        <translation>Die Falldatei ist größer, als dieses Programm zulässt.</translation>
    </message>
    <message>
        <source>The case is not valid: a value is outside its allowed range (see the details).</source>
        <translation>Der Fall ist ungültig: Ein Wert liegt außerhalb seines zulässigen Bereichs (siehe Details).</translation>
    </message>
    <message>
        <source>The case could not be opened or saved.</source>
        <translation>Der Fall konnte nicht geöffnet oder gespeichert werden.</translation>
    </message>
    <message>
        <source>Open Case</source>
        <translation>Fall öffnen</translation>
    </message>
    <message>
        <source>Cases (*.json)</source>
        <translation>Fälle (*.json)</translation>
    </message>
    <message>
        <source>Save Case</source>
        <translation>Fall speichern</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Automatisches Speichern fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <source>Recover Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen wiederherstellen</translation>
    </message>
    <message>
        <source>The last session ended with unsaved changes to the case %1. Recover them?</source>
        <translation>Die letzte Sitzung endete mit ungespeicherten Änderungen am Fall %1. Wiederherstellen?</translation>
    </message>
    <message>
        <source>Recen&amp;t Cases</source>
        <translation>Zule&amp;tzt verwendete Fälle</translation>
    </message>
    <message>
        <source>Review Scene Package</source>
        <translation>Szenenpaket begutachten</translation>
    </message>
    <message>
        <source>The scene package cannot be read: a file is missing, changed or breaks its format (see the details).</source>
        <translation>Das Szenenpaket kann nicht gelesen werden: Eine Datei fehlt, wurde geändert oder verletzt ihr Format (siehe Details).</translation>
    </message>
    <message>
        <source>Open an exported scene package read-only and rate how real it looks</source>
        <translation>Ein exportiertes Szenenpaket schreibgeschützt öffnen und bewerten, wie echt es aussieht</translation>
    </message>
    <message>
        <source>Close Re&amp;view</source>
        <translation>Begutachtung sch&amp;ließen</translation>
    </message>
    <message>
        <source>&amp;Panels</source>
        <translation>&amp;Bedienfelder</translation>
    </message>
    <message>
        <source>Patient</source>
        <translation>Patientin</translation>
    </message>
    <message>
        <source>Pathologies</source>
        <translation>Pathologien</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Materialien</translation>
    </message>
    <message>
        <source>Mesh</source>
        <translation>Netz</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Export</translation>
    </message>
    <message>
        <source>Texture</source>
        <translation>Textur</translation>
    </message>
    <message>
        <source>Review</source>
        <translation>Begutachtung</translation>
    </message>
    <message>
        <source>Hysteroscopic View</source>
        <translation>Hysteroskopische Ansicht</translation>
    </message>
    <message>
        <source>Exemplar Image</source>
        <translation>Vorlagenbild</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.exr *.tif *.tiff)</source>
        <translation>Bilder (*.png *.jpg *.jpeg *.exr *.tif *.tiff)</translation>
    </message>
    <message>
        <source>Export Scene Package</source>
        <translation>Szenenpaket exportieren</translation>
    </message>
    <message>
        <source>Reading the scene package</source>
        <translation>Szenenpaket wird gelesen</translation>
    </message>
    <message>
        <source>Unsaved Ratings</source>
        <translation>Ungespeicherte Bewertungen</translation>
    </message>
    <message>
        <source>The review of %1 has unsaved ratings. Save them?</source>
        <translation>Die Begutachtung von %1 hat ungespeicherte Bewertungen. Speichern?</translation>
    </message>
    <message>
        <source>Organ</source>
        <translation>Organ</translation>
    </message>
    <message>
        <source>Grown pathologies</source>
        <translation>Gewachsene Pathologien</translation>
    </message>
    <message>
        <source>Merged body</source>
        <translation>Vereinigter Körper</translation>
    </message>
    <message>
        <source>Tetrahedral mesh</source>
        <translation>Tetraedernetz</translation>
    </message>
    <message>
        <source>Textured surface</source>
        <translation>Texturierte Oberfläche</translation>
    </message>
    <message>
        <source>The case&apos;s %1, as the pipeline made it</source>
        <translation>%1 des Falls, Ergebnis der Pipeline</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Hysteroscene %1&lt;/h3&gt;&lt;p&gt;A scenario authoring workstation for hysteroscopy training simulators.&lt;/p&gt;&lt;p&gt;Licensed under the GNU General Public License, version 3 or later.&lt;/p&gt;&lt;p&gt;&lt;small&gt;Built with %2.&lt;/small&gt;&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Hysteroscene %1&lt;/h3&gt;&lt;p&gt;Eine Arbeitsstation zum Erstellen von Szenarien für Hysteroskopie-Trainingssimulatoren.&lt;/p&gt;&lt;p&gt;Lizenziert unter der GNU General Public License, Version 3 oder später.&lt;/p&gt;&lt;p&gt;&lt;small&gt;Erstellt mit %2.&lt;/small&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Revie&amp;w Scene Package...</source>
        <translation>Szenenpaket &amp;begutachten...</translation>
    </message>
    <message>
        <source>The folder holds no scene package (no manifest.json).</source>
        <translation>Der Ordner enthält kein Szenenpaket (keine manifest.json).</translation>
    </message>
    <message>
        <source>Compare &amp;Variants...</source>
        <translation>&amp;Varianten vergleichen...</translation>
    </message>
    <message>
        <source>Show the variants of a case side by side, as the scope sees them</source>
        <translation>Die Varianten eines Falls nebeneinander zeigen, wie das Hysteroskop sie sieht</translation>
    </message>
    <message>
        <source>Compare Variants</source>
        <translation>Varianten vergleichen</translation>
    </message>
    <message>
        <source>Reading the variants</source>
        <translation>Varianten werden gelesen</translation>
    </message>
    <message>
        <source>Variants - %1</source>
        <translation>Varianten - %1</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Rückgängig: %1</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Wiederholen: %1</translation>
    </message>
    <message>
        <source>&amp;Stages</source>
        <translation>&amp;Stufen</translation>
    </message>
    <message>
        <source>&amp;Place on the Wall</source>
        <translation>An der Wand &amp;platzieren</translation>
    </message>
    <message>
        <source>&amp;Grow</source>
        <translation>Wachsen &amp;lassen</translation>
    </message>
    <message>
        <source>&amp;Mesh</source>
        <translation>Ver&amp;netzen</translation>
    </message>
    <message>
        <source>&amp;Texture</source>
        <translation>&amp;Texturieren</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exportieren</translation>
    </message>
    <message>
        <source>Cancel Placing</source>
        <translation>Platzieren abbrechen</translation>
    </message>
    <message>
        <source>&amp;Orientation Marker</source>
        <translation>&amp;Orientierungsmarke</translation>
    </message>
    <message>
        <source>Show the patient&apos;s directions in the corner of the 3-D view</source>
        <translation>Die Richtungen der Patientin in der Ecke der 3-D-Ansicht zeigen</translation>
    </message>
    <message>
        <source>&amp;Anterior</source>
        <translation>&amp;Anterior</translation>
    </message>
    <message>
        <source>Look at the organ from in front of the patient</source>
        <translation>Das Organ von vorne betrachten</translation>
    </message>
    <message>
        <source>&amp;Posterior</source>
        <translation>&amp;Posterior</translation>
    </message>
    <message>
        <source>Look at the organ from behind the patient</source>
        <translation>Das Organ von hinten betrachten</translation>
    </message>
    <message>
        <source>&amp;Left</source>
        <translation>&amp;Links</translation>
    </message>
    <message>
        <source>Look at the organ from the patient&apos;s left</source>
        <translation>Das Organ von der linken Seite der Patientin betrachten</translation>
    </message>
    <message>
        <source>&amp;Right</source>
        <translation>&amp;Rechts</translation>
    </message>
    <message>
        <source>Look at the organ from the patient&apos;s right</source>
        <translation>Das Organ von der rechten Seite der Patientin betrachten</translation>
    </message>
    <message>
        <source>&amp;Fundal</source>
        <translation>&amp;Fundal</translation>
    </message>
    <message>
        <source>Look down the uterine axis from above the fundus</source>
        <translation>Von oberhalb des Fundus entlang der Uterusachse blicken</translation>
    </message>
    <message>
        <source>From the External &amp;Os</source>
        <translation>Vom äußeren &amp;Muttermund</translation>
    </message>
    <message>
        <source>Look up the cervical canal from the external os, as the scope enters</source>
        <translation>Vom äußeren Muttermund den Zervikalkanal hinauf blicken, wie das Hysteroskop eintritt</translation>
    </message>
    <message>
        <source>Look &amp;From</source>
        <translation>&amp;Ansicht von</translation>
    </message>
    <message>
        <source>Views</source>
        <translation>Ansichten</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <source>Out of date: the case has changed since this scene was made.</source>
        <translation>Veraltet: Der Fall wurde geändert, seit diese Szene erstellt wurde.</translation>
    </message>
    <message>
        <source>on %1</source>
        <translation>auf %1</translation>
    </message>
    <message>
        <source>Out of date (%1): the case has changed since this view was made. It is remade when its stage runs again.</source>
        <translation>Veraltet (%1): Der Fall wurde geändert, seit diese Ansicht erstellt wurde. Sie wird neu erstellt, wenn ihr Schritt erneut läuft.</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Öffnen</translation>
    </message>
    <message>
        <source>A scene package is being reviewed, read-only: close the review (File &gt; Close Review) before opening %1.</source>
        <translation>Ein Szenenpaket wird schreibgeschützt bewertet: Schließen Sie die Bewertung (Datei &gt; Bewertung schließen), bevor Sie %1 öffnen.</translation>
    </message>
    <message>
        <source>The folder %1 holds no scene package (no manifest.json).</source>
        <translation>Der Ordner %1 enthält kein Szenenpaket (keine manifest.json).</translation>
    </message>
    <message>
        <source>%1 is not a file this program opens: it opens cases (.json), scene packages (a folder with a manifest.json) and meshes (%2).</source>
        <translation>%1 ist keine Datei, die dieses Programm öffnet: Es öffnet Fälle (.json), Szenenpakete (ein Ordner mit einer manifest.json) und Netze (%2).</translation>
    </message>
    <message>
        <source>Package Changed on Disk</source>
        <translation>Paket auf der Festplatte geändert</translation>
    </message>
    <message>
        <source>The scene package %1 has changed on disk since it was opened for review. Reload it? The ratings stay with the version you opened.</source>
        <translation>Das Szenenpaket %1 wurde auf der Festplatte geändert, seit es zur Bewertung geöffnet wurde. Neu laden? Die Bewertungen bleiben bei der geöffneten Version.</translation>
    </message>
    <message>
        <source>The package has changed on disk since it was opened: what is shown, and rated, is the version opened.</source>
        <translation>Das Paket wurde seit dem Öffnen auf der Festplatte geändert: Gezeigt und bewertet wird die geöffnete Version.</translation>
    </message>
    <message>
        <source>The case %1 has changed on disk, and you have unsaved changes. Reload it from disk? Your changes are lost.</source>
        <translation>Der Fall %1 wurde auf der Festplatte geändert, und Sie haben ungespeicherte Änderungen. Von der Festplatte neu laden? Ihre Änderungen gehen verloren.</translation>
    </message>
    <message>
        <source>The case %1 has changed on disk. Reload it?</source>
        <translation>Der Fall %1 wurde auf der Festplatte geändert. Neu laden?</translation>
    </message>
    <message>
        <source>Case Changed on Disk</source>
        <translation>Fall auf der Festplatte geändert</translation>
    </message>
    <message>
        <source>The case on disk differs from the one open; Save writes this one over it.</source>
        <translation>Der Fall auf der Festplatte unterscheidet sich vom geöffneten; Speichern überschreibt ihn mit diesem.</translation>
    </message>
    <message>
        <source>The case file %1 is gone from disk; Save writes it again.</source>
        <translation>Die Falldatei %1 ist nicht mehr auf der Festplatte; Speichern schreibt sie erneut.</translation>
    </message>
    <message>
        <source>Review Trial Report</source>
        <translation>Durchlaufbericht begutachten</translation>
    </message>
    <message>
        <source>The trial report cannot be read: it is missing or breaks its format (see the details).</source>
        <translation>Der Durchlaufbericht kann nicht gelesen werden: Er fehlt oder verletzt sein Format (siehe Details).</translation>
    </message>
    <message>
        <source>Review Trial Re&amp;port...</source>
        <translation>D&amp;urchlaufbericht begutachten...</translation>
    </message>
    <message>
        <source>Show a simulator trial&apos;s metrics and plots from its report</source>
        <translation>Die Messwerte und Verläufe eines Simulator-Durchlaufs aus seinem Bericht zeigen</translation>
    </message>
    <message>
        <source>Trial reports (*.json);;All files (*)</source>
        <translation>Durchlaufberichte (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Reading the trial report</source>
        <translation>Durchlaufbericht wird gelesen</translation>
    </message>
    <message>
        <source>Trial Report - %1</source>
        <translation>Durchlaufbericht - %1</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>Wiedergabe</translation>
    </message>
    <message>
        <source>The simulator is not installed beside the workstation.</source>
        <translation>Der Simulator ist nicht neben der Workstation installiert.</translation>
    </message>
    <message>
        <source>No executable %1.</source>
        <translation>Keine ausführbare Datei %1.</translation>
    </message>
    <message>
        <source>The Scene Package the Trial Ran On</source>
        <translation>Das Szenenpaket des Durchlaufs</translation>
    </message>
    <message>
        <source>The simulator did not start.</source>
        <translation>Der Simulator ist nicht gestartet.</translation>
    </message>
    <message>
        <source>Replaying %1 in the simulator.</source>
        <translation>%1 wird im Simulator wiedergegeben.</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Scenario authoring workstation for hysteroscopy training</source>
        <translation>Arbeitsstation zum Erstellen von Szenarien für das Hysteroskopie-Training</translation>
    </message>
    <message>
        <source>file</source>
        <translation>Datei</translation>
    </message>
    <message>
        <source>User-interface language (de, fr, it, en); default: HS_LANG, else the system locale.</source>
        <translation>Sprache der Benutzeroberfläche (de, fr, it, en); Vorgabe: HS_LANG, sonst die Systemeinstellung.</translation>
    </message>
    <message>
        <source>language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <source>Save the window to an image after loading, then quit.</source>
        <translation>Das Fenster nach dem Laden als Bild speichern und beenden.</translation>
    </message>
    <message>
        <source>image</source>
        <translation>Bild</translation>
    </message>
    <message>
        <source>Open a tetrahedral mesh cut open.</source>
        <translation>Ein Tetraedernetz aufgeschnitten öffnen.</translation>
    </message>
    <message>
        <source>A case file (.json) to author, a scene package (a folder) or a simulator&apos;s trial report (.json) to review, or a surface or tetrahedral mesh to open.</source>
        <translation>Eine Falldatei (.json) zum Bearbeiten, ein Szenenpaket (ein Ordner) oder ein Durchlaufbericht des Simulators (.json) zur Begutachtung oder eine Oberfläche bzw. ein Tetraedernetz zum Öffnen.</translation>
    </message>
</context>
</TS>
