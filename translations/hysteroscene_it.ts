<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="it">
<context>
    <name>hs::widgets::CaseDocument</name>
    <message>
        <source>Untitled</source>
        <translation>Senza titolo</translation>
    </message>
    <message>
        <source>Recover unsaved changes</source>
        <translation>Recupera le modifiche non salvate</translation>
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
        <translation>&amp;Apri...</translation>
    </message>
    <message>
        <source>Open a surface or tetrahedral mesh</source>
        <translation>Apri una superficie o una mesh tetraedrica</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Esci</translation>
    </message>
    <message>
        <source>&amp;Clear Menu</source>
        <translation>&amp;Svuota menu</translation>
    </message>
    <message>
        <source>&amp;Clip</source>
        <translation>Se&amp;zione</translation>
    </message>
    <message>
        <source>Cut the tetrahedral mesh open and show the tetrahedra on the cut</source>
        <translation>Taglia la mesh tetraedrica e mostra i tetraedri sul taglio</translation>
    </message>
    <message>
        <source>&amp;Reset Camera</source>
        <translation>&amp;Reimposta la telecamera</translation>
    </message>
    <message>
        <source>&amp;About Hysteroscene</source>
        <translation>&amp;Informazioni su Hysteroscene</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>File &amp;recenti</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Visualizza</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Aiuto</translation>
    </message>
    <message>
        <source>All meshes (%1)</source>
        <translation>Tutte le mesh (%1)</translation>
    </message>
    <message>
        <source>Surface meshes (%1)</source>
        <translation>Mesh di superficie (%1)</translation>
    </message>
    <message>
        <source>Tetrahedral meshes (%1)</source>
        <translation>Mesh tetraedriche (%1)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Tutti i file (*)</translation>
    </message>
    <message>
        <source>Open Mesh</source>
        <translation>Apri mesh</translation>
    </message>
    <message>
        <source>Opening %1...</source>
        <translation>Apertura di %1...</translation>
    </message>
    <message>
        <source>The file %1 does not exist.</source>
        <translation>Il file %1 non esiste.</translation>
    </message>
    <message>
        <source>The file %1 could not be read.</source>
        <translation>Impossibile leggere il file %1.</translation>
    </message>
    <message>
        <source>The file %1 is in a format or version this program does not read.</source>
        <translation>Il file %1 è in un formato o in una versione che questo programma non legge.</translation>
    </message>
    <message>
        <source>The file %1 is larger than this program accepts.</source>
        <translation>Il file %1 supera le dimensioni accettate da questo programma.</translation>
    </message>
    <message>
        <source>The file %1 is not a valid mesh.</source>
        <translation>Il file %1 non è una mesh valida.</translation>
    </message>
    <message>
        <source>The file %1 could not be opened.</source>
        <translation>Impossibile aprire il file %1.</translation>
    </message>
    <message>
        <source>Nothing picked</source>
        <translation>Nessun punto selezionato</translation>
    </message>
    <message>
        <source>Picked (%1, %2, %3) mm</source>
        <translation>Punto selezionato (%1; %2; %3) mm</translation>
    </message>
    <message>
        <source>No mesh</source>
        <translation>Nessuna mesh</translation>
    </message>
    <message>
        <source>Vertices: %1   Tetrahedra: %2   Regions: %3</source>
        <translation>Vertici: %1   Tetraedri: %2   Regioni: %3</translation>
    </message>
    <message>
        <source>Shown: %1</source>
        <translation>Visualizzati: %1</translation>
    </message>
    <message>
        <source>Vertices: %1   Triangles: %2   Regions: %3</source>
        <translation>Vertici: %1   Triangoli: %2   Regioni: %3</translation>
    </message>
    <message>
        <source>About Hysteroscene</source>
        <translation>Informazioni su Hysteroscene</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Hysteroscene %1&lt;/h3&gt;&lt;p&gt;A scenario authoring workstation for hysteroscopy training simulators.&lt;/p&gt;&lt;p&gt;Licensed under the GNU General Public License, version 3 or later.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Hysteroscene %1&lt;/h3&gt;&lt;p&gt;Una postazione per la creazione di scenari per simulatori di addestramento all&apos;isteroscopia.&lt;/p&gt;&lt;p&gt;Distribuito con la licenza GNU General Public License, versione 3 o successiva.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;New Case</source>
        <translation>&amp;Nuovo caso</translation>
    </message>
    <message>
        <source>Start a new case from the default patient</source>
        <translation>Inizia un nuovo caso dalla paziente predefinita</translation>
    </message>
    <message>
        <source>Open &amp;Case...</source>
        <translation>Apri &amp;caso...</translation>
    </message>
    <message>
        <source>Open a case file (case.json)</source>
        <translation>Apri un file di caso (case.json)</translation>
    </message>
    <message>
        <source>&amp;Save Case</source>
        <translation>&amp;Salva caso</translation>
    </message>
    <message>
        <source>Save Case &amp;As...</source>
        <translation>Salva caso &amp;come...</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Annulla</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Ripeti</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Modifica</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Modifiche non salvate</translation>
    </message>
    <message>
        <source>The case %1 has unsaved changes. Save them?</source>
        <translation>Il caso %1 ha modifiche non salvate. Salvarle?</translation>
    </message>
    <message>
        <source>The case file does not exist.</source>
        <translation>Il file del caso non esiste.</translation>
    </message>
    <message>
        <source>The case file could not be read or written.</source>
        <translation>Il file del caso non può essere letto o scritto.</translation>
    </message>
    <message>
        <source>The case file is of a version this program does not read.</source>
        <translation>Il file del caso è di una versione che questo programma non legge.</translation>
    </message>
    <message>
        <source>The case file is larger than this program accepts.</source>
        <translation>Il file del caso è più grande di quanto questo programma accetti.</translation>
    </message>
    <message>
        <source>The case is not valid: a value is outside its allowed range (see the details).</source>
        <translation>Il caso non è valido: un valore è fuori dal suo intervallo consentito (vedi i dettagli).</translation>
    </message>
    <message>
        <source>The case could not be opened or saved.</source>
        <translation>Il caso non può essere aperto o salvato.</translation>
    </message>
    <message>
        <source>Open Case</source>
        <translation>Apri caso</translation>
    </message>
    <message>
        <source>Cases (*.json)</source>
        <translation>Casi (*.json)</translation>
    </message>
    <message>
        <source>Save Case</source>
        <translation>Salva caso</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Salvataggio automatico non riuscito: %1</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Senza titolo</translation>
    </message>
    <message>
        <source>Recover Unsaved Changes</source>
        <translation>Recupera le modifiche non salvate</translation>
    </message>
    <message>
        <source>The last session ended with unsaved changes to the case %1. Recover them?</source>
        <translation>L&apos;ultima sessione si è chiusa con modifiche non salvate al caso %1. Recuperarle?</translation>
    </message>
    <message>
        <source>Recen&amp;t Cases</source>
        <translation>Casi recen&amp;ti</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Scenario authoring workstation for hysteroscopy training</source>
        <translation>Postazione per la creazione di scenari per l&apos;addestramento all&apos;isteroscopia</translation>
    </message>
    <message>
        <source>file</source>
        <translation>file</translation>
    </message>
    <message>
        <source>A surface or tetrahedral mesh to open.</source>
        <translation>Una superficie o una mesh tetraedrica da aprire.</translation>
    </message>
    <message>
        <source>User-interface language (de, fr, it, en); default: HS_LANG, else the system locale.</source>
        <translation>Lingua dell&apos;interfaccia (de, fr, it, en); predefinita: HS_LANG, altrimenti la lingua del sistema.</translation>
    </message>
    <message>
        <source>language</source>
        <translation>lingua</translation>
    </message>
    <message>
        <source>Save the window to an image after loading, then quit.</source>
        <translation>Salva la finestra come immagine dopo il caricamento, poi esci.</translation>
    </message>
    <message>
        <source>image</source>
        <translation>immagine</translation>
    </message>
    <message>
        <source>Open a tetrahedral mesh cut open.</source>
        <translation>Apri una mesh tetraedrica sezionata.</translation>
    </message>
</context>
</TS>
