<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de">
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
        <source>&lt;h3&gt;Hysteroscene %1&lt;/h3&gt;&lt;p&gt;A scenario authoring workstation for hysteroscopy training simulators.&lt;/p&gt;&lt;p&gt;Licensed under the GNU General Public License, version 3 or later.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Hysteroscene %1&lt;/h3&gt;&lt;p&gt;Eine Arbeitsstation zum Erstellen von Szenarien für Hysteroskopie-Trainingssimulatoren.&lt;/p&gt;&lt;p&gt;Lizenziert unter der GNU General Public License, Version 3 oder später.&lt;/p&gt;</translation>
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
        <source>A surface or tetrahedral mesh to open.</source>
        <translation>Eine zu öffnende Oberfläche oder ein Tetraedernetz.</translation>
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
</context>
</TS>
