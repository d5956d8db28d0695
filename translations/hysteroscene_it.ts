<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="it">
<context>
    <name>hs::simapp::SimWindow</name>
    <message>
        <source>&amp;Polypectomy: resect the polyps with the loop</source>
        <translation>&amp;Polipectomia: resecare i polipi con l&apos;ansa</translation>
    </message>
    <message>
        <source>&amp;Myomectomy: resect the submucous myomas with the loop</source>
        <translation>&amp;Miomectomia: resecare i miomi sottomucosi con l&apos;ansa</translation>
    </message>
    <message>
        <source>This device speaks version 1 of the hysteroscope protocol: it drives the diagnostic scope only. The resectoscope&apos;s loop, pedals and pump buttons need a device of version 2 (docs/haptics-protocol.md); without one the %1 exercise cannot cut.</source>
        <translation>Questo dispositivo parla la versione 1 del protocollo dell&apos;isteroscopio: guida solo l&apos;isteroscopio diagnostico. L&apos;ansa, i pedali e i pulsanti della pompa del resettoscopio richiedono un dispositivo di versione 2 (docs/haptics-protocol.md); senza di esso l&apos;esercizio %1 non può tagliare.</translation>
    </message>
    <message>
        <source>&lt;p&gt;The instruments (polypectomy, myomectomy) and the pump:&lt;/p&gt;&lt;table&gt;&lt;tr&gt;&lt;td&gt;L&lt;/td&gt;&lt;td&gt;the next instrument: the resectoscope&apos;s loop, scissors, grasper, none&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;R / F&lt;/td&gt;&lt;td&gt;push the instrument out / draw it in (the working element)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;C, held&lt;/td&gt;&lt;td&gt;the cutting pedal (scissors and grasper: close the jaws)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;V, held&lt;/td&gt;&lt;td&gt;the coagulating pedal&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;+ / -&lt;/td&gt;&lt;td&gt;raise / lower the pump&apos;s set pressure by 5 mmHg&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;p&gt;Gli strumenti (polipectomia, miomectomia) e la pompa:&lt;/p&gt;&lt;table&gt;&lt;tr&gt;&lt;td&gt;L&lt;/td&gt;&lt;td&gt;lo strumento successivo: l&apos;ansa del resettoscopio, forbici, pinza da presa, nessuno&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;R / F&lt;/td&gt;&lt;td&gt;spingere fuori / ritirare lo strumento (l&apos;elemento di lavoro)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;C, tenuto&lt;/td&gt;&lt;td&gt;il pedale di taglio (forbici e pinza: chiudere le branche)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;V, tenuto&lt;/td&gt;&lt;td&gt;il pedale di coagulazione&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;+ / -&lt;/td&gt;&lt;td&gt;alzare / abbassare la pressione impostata della pompa di 5 mmHg&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
    <message>
        <source>hysteroscene simulator</source>
        <translation>Simulatore hysteroscene</translation>
    </message>
    <message>
        <source>Open a scene package (File &gt; Open).</source>
        <translation>Apri un pacchetto di scena (File &gt; Apri pacchetto).</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <source>&amp;Open Package...</source>
        <translation>&amp;Apri pacchetto...</translation>
    </message>
    <message>
        <source>&amp;End Trial and Show Report...</source>
        <translation>&amp;Termina la prova e mostra il rapporto...</translation>
    </message>
    <message>
        <source>&amp;Restart Trial</source>
        <translation>&amp;Riavvia la prova</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Esci</translation>
    </message>
    <message>
        <source>&amp;Scope</source>
        <translation>&amp;Isteroscopio</translation>
    </message>
    <message>
        <source>&amp;Optic</source>
        <translation>&amp;Ottica</translation>
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
        <translation>&amp;Diametro</translation>
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
        <translation>&amp;Esercizio</translation>
    </message>
    <message>
        <source>&amp;Exploration: see the fundus, both ostia and every wall</source>
        <translation>&amp;Esplorazione: vedere il fondo, entrambi gli osti tubarici e ogni parete</translation>
    </message>
    <message>
        <source>&amp;Diagnosis: mark each pathology</source>
        <translation>&amp;Diagnosi: contrassegnare ogni patologia</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Aiuto</translation>
    </message>
    <message>
        <source>&amp;Keys...</source>
        <translation>&amp;Tasti...</translation>
    </message>
    <message>
        <source>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Arrow keys, or drag with the mouse&lt;/td&gt;&lt;td&gt;turn the scope about the cervix (pitch, yaw)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;W / S, or the mouse wheel&lt;/td&gt;&lt;td&gt;insert / withdraw&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Q / E&lt;/td&gt;&lt;td&gt;roll the scope (an oblique optic looks round)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Z / X&lt;/td&gt;&lt;td&gt;roll the camera head (the image&apos;s horizon)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;I / O&lt;/td&gt;&lt;td&gt;open or close the inflow / outflow valve&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Space&lt;/td&gt;&lt;td&gt;mark the pathology at the centre of the view&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Ctrl+E&lt;/td&gt;&lt;td&gt;end the trial and show the report&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Ctrl+R&lt;/td&gt;&lt;td&gt;restart the trial&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;F1&lt;/td&gt;&lt;td&gt;this help&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Tasti freccia, o trascinare con il mouse&lt;/td&gt;&lt;td&gt;orientare l&apos;isteroscopio attorno alla cervice (su/giù, sinistra/destra)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;W / S, o la rotellina del mouse&lt;/td&gt;&lt;td&gt;inserire / ritirare&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Q / E&lt;/td&gt;&lt;td&gt;ruotare l&apos;isteroscopio sul suo asse (un&apos;ottica angolata guarda di lato)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Z / X&lt;/td&gt;&lt;td&gt;ruotare la testa della telecamera (l&apos;orizzonte dell&apos;immagine)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;I / O&lt;/td&gt;&lt;td&gt;aprire o chiudere la valvola di afflusso / deflusso&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Spazio&lt;/td&gt;&lt;td&gt;contrassegnare la patologia al centro della vista&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Ctrl+E&lt;/td&gt;&lt;td&gt;terminare la prova e mostrare il rapporto&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Ctrl+R&lt;/td&gt;&lt;td&gt;riavviare la prova&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;F1&lt;/td&gt;&lt;td&gt;questa guida&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
    <message>
        <source>Keys</source>
        <translation>Tasti</translation>
    </message>
    <message>
        <source>Loading %1...</source>
        <translation>Caricamento di %1...</translation>
    </message>
    <message>
        <source>The package could not be loaded.</source>
        <translation>Impossibile caricare il pacchetto.</translation>
    </message>
    <message>
        <source>Open Package</source>
        <translation>Apri pacchetto</translation>
    </message>
    <message>
        <source>The scene package could not be loaded.</source>
        <translation>Impossibile caricare il pacchetto di scena.</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>Riproduzione</translation>
    </message>
    <message>
        <source>The trial could not be read.</source>
        <translation>Impossibile leggere la registrazione della prova.</translation>
    </message>
    <message>
        <source>Script</source>
        <translation>Script</translation>
    </message>
    <message>
        <source>The script could not be read.</source>
        <translation>Impossibile leggere lo script.</translation>
    </message>
    <message>
        <source>Haptic device</source>
        <translation>Dispositivo aptico</translation>
    </message>
    <message>
        <source>The haptic hysteroscope could not be opened.</source>
        <translation>Impossibile aprire l&apos;isteroscopio aptico.</translation>
    </message>
    <message>
        <source>hysteroscene simulator: %1</source>
        <translation>Simulatore hysteroscene: %1</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulazione</translation>
    </message>
    <message>
        <source>The simulation stopped.</source>
        <translation>La simulazione si è interrotta.</translation>
    </message>
    <message>
        <source>The device&apos;s samples have ended: File &gt; End Trial shows the report.</source>
        <translation>I campioni del dispositivo sono terminati: File &gt; Termina la prova mostra il rapporto.</translation>
    </message>
    <message>
        <source>Save the Trial&apos;s Report</source>
        <translation>Salva il rapporto della prova</translation>
    </message>
    <message>
        <source>Trial reports (*.json)</source>
        <translation>Rapporti di prova (*.json)</translation>
    </message>
    <message>
        <source>Trial Report</source>
        <translation>Rapporto della prova</translation>
    </message>
    <message>
        <source>The report is in %1. Open it?</source>
        <translation>Il rapporto è in %1. Aprirlo?</translation>
    </message>
    <message>
        <source>The report could not be written.</source>
        <translation>Impossibile scrivere il rapporto.</translation>
    </message>
    <message>
        <source>Trial ended; report written to %1.</source>
        <translation>Prova terminata; rapporto scritto in %1.</translation>
    </message>
    <message>
        <source>Open a Scene Package</source>
        <translation>Apri un pacchetto di scena</translation>
    </message>
    <message>
        <source> (light view: software GL)</source>
        <translation> (vista leggera: GL software)</translation>
    </message>
    <message>
        <source>%L1 fps%4, physics %L2 steps/s, insertion %L3 mm</source>
        <translation>%L1 fps%4, fisica %L2 passi/s, inserimento %L3 mm</translation>
    </message>
    <message>
        <source>The trial was recorded with other settings.</source>
        <translation>La prova è stata registrata con altre impostazioni.</translation>
    </message>
    <message>
        <source>Demonstration</source>
        <translation>Dimostrazione</translation>
    </message>
    <message>
        <source>The demonstration could not be planned.</source>
        <translation>Non è stato possibile pianificare la dimostrazione.</translation>
    </message>
</context>
<context>
    <name>hs::widgets</name>
    <message>
        <source>Gravidity counts every pregnancy, so it cannot be less than the parity.</source>
        <translation>Il numero di gravidanze comprende ogni gravidanza, quindi non può essere inferiore alla parità.</translation>
    </message>
    <message>
        <source>A postmenopausal patient is at least 40 years old, a premenopausal one at most 60.</source>
        <translation>Una paziente in postmenopausa ha almeno 40 anni, una in premenopausa al massimo 60.</translation>
    </message>
    <message>
        <source>Only a premenopausal patient has a cycle phase.</source>
        <translation>Solo una paziente in premenopausa ha una fase del ciclo.</translation>
    </message>
    <message>
        <source>The cavity must be shorter than the uterus.</source>
        <translation>La cavità deve essere più corta dell&apos;utero.</translation>
    </message>
    <message>
        <source>The cavity must be narrower than the uterus.</source>
        <translation>La cavità deve essere più stretta dell&apos;utero.</translation>
    </message>
    <message>
        <source>Myomas are 5 – 100 mm, polyps 3 – 40 mm in size.</source>
        <translation>I miomi misurano 5 – 100 mm, i polipi 3 – 40 mm.</translation>
    </message>
    <message>
        <source>A case holds at most %1 pathologies.</source>
        <translation>Un caso contiene al massimo %1 patologie.</translation>
    </message>
    <message>
        <source>This value is not allowed here (%1).</source>
        <translation>Questo valore non è consentito qui (%1).</translation>
    </message>
    <message>
        <source>An id is 1 – 32 letters, digits, &apos;-&apos; or &apos;_&apos;, starts with a letter or digit, and is unique in the case.</source>
        <translation>Un identificativo ha 1 – 32 lettere, cifre, &apos;-&apos; o &apos;_&apos;, inizia con una lettera o una cifra ed è unico nel caso.</translation>
    </message>
    <message>
        <source>Young&apos;s modulus must be in the range %1.</source>
        <translation>Il modulo di Young deve essere nell&apos;intervallo %1.</translation>
    </message>
    <message>
        <source>The Poisson ratio must be in the range %1.</source>
        <translation>Il coefficiente di Poisson deve essere nell&apos;intervallo %1.</translation>
    </message>
    <message>
        <source>The density must be in the range %1.</source>
        <translation>La densità deve essere nell&apos;intervallo %1.</translation>
    </message>
    <message>
        <source>The heterogeneity must be in the range %1.</source>
        <translation>L&apos;eterogeneità deve essere nell&apos;intervallo %1.</translation>
    </message>
    <message>
        <source>The hydrometra pressure must be in the range %1.</source>
        <translation>La pressione dell&apos;idrometra deve essere nell&apos;intervallo %1.</translation>
    </message>
    <message>
        <source>%1 must be in the range %2.</source>
        <translation>«%1» deve essere nell&apos;intervallo %2.</translation>
    </message>
</context>
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
    <name>hs::widgets::CaseEdits</name>
    <message>
        <source>Age</source>
        <translation>Età</translation>
    </message>
    <message>
        <source>years</source>
        <translation>anni</translation>
    </message>
    <message>
        <source>Parity</source>
        <translation>Parità</translation>
    </message>
    <message>
        <source>births</source>
        <translation>parti</translation>
    </message>
    <message>
        <source>Gravidity</source>
        <translation>Gravidanze</translation>
    </message>
    <message>
        <source>pregnancies</source>
        <translation>gravidanze</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Altezza</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Peso</translation>
    </message>
    <message>
        <source>Uterine length</source>
        <translation>Lunghezza uterina</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Larghezza</translation>
    </message>
    <message>
        <source>AP depth</source>
        <translation>Profondità AP</translation>
    </message>
    <message>
        <source>Cavity length</source>
        <translation>Lunghezza della cavità</translation>
    </message>
    <message>
        <source>Cavity width</source>
        <translation>Larghezza della cavità</translation>
    </message>
    <message>
        <source>Cervix length</source>
        <translation>Lunghezza della cervice</translation>
    </message>
    <message>
        <source>Stalk length</source>
        <translation>Lunghezza del peduncolo</translation>
    </message>
    <message>
        <source>Target vertices</source>
        <translation>Vertici obiettivo</translation>
    </message>
    <message>
        <source>Vessel density</source>
        <translation>Densità vascolare</translation>
    </message>
    <message>
        <source>Fundal wall thickness</source>
        <translation>Spessore della parete fundica</translation>
    </message>
</context>
<context>
    <name>hs::widgets::ExportPanel</name>
    <message>
        <source>Scene package</source>
        <translation>Pacchetto di scena</translation>
    </message>
    <message>
        <source>Folder of the package</source>
        <translation>Cartella del pacchetto</translation>
    </message>
    <message>
        <source>The package is written to this folder (created; an existing package is replaced)</source>
        <translation>Il pacchetto viene scritto in questa cartella (creata se necessario; un pacchetto esistente viene sostituito)</translation>
    </message>
    <message>
        <source>&amp;Browse...</source>
        <translation>Sf&amp;oglia...</translation>
    </message>
    <message>
        <source>&amp;Folder</source>
        <translation>&amp;Cartella</translation>
    </message>
    <message>
        <source>Also as a .zip</source>
        <translation>Anche come .zip</translation>
    </message>
    <message>
        <source>Also the formats of other tools: glTF, Gmsh MSH, OBJ, SOFA</source>
        <translation>Anche i formati di altri strumenti: glTF, Gmsh MSH, OBJ, SOFA</translation>
    </message>
    <message>
        <source>More than one: a new patient of the same description per variant, each in folder/variant-NNN with its own seed</source>
        <translation>Più di una: una nuova paziente con la stessa descrizione per ogni variante, ciascuna in cartella/variant-NNN con il proprio seme</translation>
    </message>
    <message>
        <source>&amp;Variants</source>
        <translation>&amp;Varianti</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Esporta</translation>
    </message>
    <message>
        <source>Run what is not current, write the package and validate it (Ctrl+E)</source>
        <translation>Esegui ciò che non è aggiornato, scrivi il pacchetto e convalidalo (Ctrl+E)</translation>
    </message>
    <message>
        <source>Open in &amp;Simulator</source>
        <translation>Apri nel &amp;simulatore</translation>
    </message>
    <message>
        <source>The preview simulator is not installed with this workstation</source>
        <translation>Il simulatore di anteprima non è installato con questa postazione</translation>
    </message>
    <message>
        <source>Start the preview simulator on the exported package</source>
        <translation>Avvia il simulatore di anteprima sul pacchetto esportato</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;Choose a folder for the package first.&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;Scegli prima una cartella per il pacchetto.&lt;/span&gt;</translation>
    </message>
    <message>
        <source>Exporting...</source>
        <translation>Esportazione...</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: valid, %2 files with matching checksums (seed %3).</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;: valido, %2 file con checksum corrispondenti (seme %3).</translation>
    </message>
    <message>
        <source>Zipped as %1.</source>
        <translation>Compresso come %1.</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;The simulator could not be started.&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;Impossibile avviare il simulatore.&lt;/span&gt;</translation>
    </message>
    <message>
        <source>The scope&apos;s passage could not be checked: %1</source>
        <translation>Non è stato possibile verificare il passaggio dell&apos;isteroscopio: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s), also in scene.json:</source>
        <translation>
            <numerusform>%n avviso, anche in scene.json:</numerusform>
            <numerusform>%n avvisi, anche in scene.json:</numerusform>
        </translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;A %1 mm scope does not pass the cervical canal (narrowest %2 mm).&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;Un isteroscopio da %1 mm non attraversa il canale cervicale (punto più stretto %2 mm).&lt;/span&gt;</translation>
    </message>
    <message>
        <source>A %1 mm scope passes the cervical canal (narrowest %2 mm) and reaches the fundus (narrowest %3 mm).</source>
        <translation>Un isteroscopio da %1 mm attraversa il canale cervicale (punto più stretto %2 mm) e raggiunge il fondo (punto più stretto %3 mm).</translation>
    </message>
    <message>
        <source>A %1 mm scope passes the cervical canal (narrowest %2 mm); a pathology narrows the way to the fundus to %3 mm.</source>
        <translation>Un isteroscopio da %1 mm attraversa il canale cervicale (punto più stretto %2 mm); una patologia restringe la via verso il fondo a %3 mm.</translation>
    </message>
</context>
<context>
    <name>hs::widgets::GenerationSession</name>
    <message>
        <source>Building the organ</source>
        <translation>Costruzione dell&apos;organo</translation>
    </message>
    <message>
        <source>Growing the pathologies</source>
        <translation>Crescita delle patologie</translation>
    </message>
    <message>
        <source>Merging the body</source>
        <translation>Unione del corpo</translation>
    </message>
    <message>
        <source>Meshing</source>
        <translation>Generazione della mesh</translation>
    </message>
    <message>
        <source>Texturing</source>
        <translation>Applicazione delle texture</translation>
    </message>
    <message>
        <source>Assembling the scene</source>
        <translation>Assemblaggio della scena</translation>
    </message>
    <message>
        <source>Exporting the scene</source>
        <translation>Esportazione della scena</translation>
    </message>
</context>
<context>
    <name>hs::widgets::HysteroscopicPreview</name>
    <message>
        <source>How far the scope&apos;s tip is beyond the external os (mm)</source>
        <translation>Distanza della punta dell&apos;isteroscopio oltre l&apos;orifizio uterino esterno (mm)</translation>
    </message>
    <message>
        <source>&amp;Insertion</source>
        <translation>&amp;Inserimento</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>The optic&apos;s angle off the shaft; office scopes are typically 30°</source>
        <translation>Angolo dell&apos;ottica rispetto all&apos;asse della camicia; gli isteroscopi office hanno di solito 30°</translation>
    </message>
    <message>
        <source>&amp;Optic</source>
        <translation>&amp;Ottica</translation>
    </message>
    <message>
        <source>The light post&apos;s rotation about the shaft (degrees; 0 looks anterior)</source>
        <translation>Rotazione dell&apos;attacco della luce attorno alla camicia (gradi; 0 guarda in avanti)</translation>
    </message>
    <message>
        <source>&amp;Roll</source>
        <translation>&amp;Rotazione</translation>
    </message>
    <message>
        <source>Texture the case to see the cavity.</source>
        <translation>Applica le texture al caso per vedere la cavità.</translation>
    </message>
    <message>
        <source>This scene has no cervical canal or ostium labels: the scope cannot be placed.</source>
        <translation>Questa scena non ha etichette per il canale cervicale o l&apos;orifizio: non è possibile posizionare l&apos;isteroscopio.</translation>
    </message>
    <message>
        <source>Tip %1 mm beyond the external os, %2 optic, roll %3°</source>
        <translation>Punta %1 mm oltre l&apos;orifizio esterno, ottica %2, rotazione %3°</translation>
    </message>
    <message>
        <source>Looking at region %1 from %2 mm inside the cavity</source>
        <translation>Vista della regione %1 da %2 mm di distanza, dall&apos;interno della cavità</translation>
    </message>
</context>
<context>
    <name>hs::widgets::JobRunner</name>
    <message>
        <source>The case asks for something the pipeline cannot make: a value is outside its allowed range or a pathology does not fit (see the details).</source>
        <translation>Il caso richiede qualcosa che la pipeline non può produrre: un valore è fuori dal suo intervallo consentito o una patologia non trova spazio (vedi i dettagli).</translation>
    </message>
    <message>
        <source>A file the case names does not exist.</source>
        <translation>Un file indicato nel caso non esiste.</translation>
    </message>
    <message>
        <source>A file could not be read or written.</source>
        <translation>Non è stato possibile leggere o scrivere un file.</translation>
    </message>
    <message>
        <source>The case asks for something this version does not support.</source>
        <translation>Il caso richiede qualcosa che questa versione non supporta.</translation>
    </message>
    <message>
        <source>The result would be larger than this program accepts.</source>
        <translation>Il risultato supererebbe le dimensioni accettate da questo programma.</translation>
    </message>
    <message>
        <source>The job was cancelled.</source>
        <translation>L&apos;operazione è stata annullata.</translation>
    </message>
    <message>
        <source>A geometry or image library failed on this case.</source>
        <translation>Una libreria di geometria o di immagini non è riuscita a elaborare questo caso.</translation>
    </message>
    <message>
        <source>An internal error stopped the job.</source>
        <translation>Un errore interno ha interrotto l&apos;operazione.</translation>
    </message>
</context>
<context>
    <name>hs::widgets::JobStatusWidget</name>
    <message>
        <source>Cancel</source>
        <translation>Annulla</translation>
    </message>
    <message>
        <source>Stop the running job (Esc)</source>
        <translation>Interrompi l&apos;operazione in corso (Esc)</translation>
    </message>
    <message>
        <source>organ from the shape model</source>
        <translation>organo dal modello di forma</translation>
    </message>
    <message>
        <source>pathologies</source>
        <translation>patologie</translation>
    </message>
    <message>
        <source>growing the pathologies</source>
        <translation>crescita delle patologie</translation>
    </message>
    <message>
        <source>measuring the pathologies</source>
        <translation>misura delle patologie</translation>
    </message>
    <message>
        <source>merging</source>
        <translation>unione</translation>
    </message>
    <message>
        <source>joining the organ and the pathologies</source>
        <translation>unione dell’organo e delle patologie</translation>
    </message>
    <message>
        <source>labelling the contacts</source>
        <translation>etichettatura dei contatti</translation>
    </message>
    <message>
        <source>covering the pathologies</source>
        <translation>copertura delle patologie</translation>
    </message>
    <message>
        <source>checking the merged body</source>
        <translation>verifica del corpo unito</translation>
    </message>
    <message>
        <source>meshing the body</source>
        <translation>generazione della mesh del corpo</translation>
    </message>
    <message>
        <source>voxelizing the body</source>
        <translation>voxelizzazione del corpo</translation>
    </message>
    <message>
        <source>seeding the particles</source>
        <translation>semina delle particelle</translation>
    </message>
    <message>
        <source>relaxing the particles</source>
        <translation>rilassamento delle particelle</translation>
    </message>
    <message>
        <source>tetrahedralizing</source>
        <translation>tetraedrizzazione</translation>
    </message>
    <message>
        <source>removing slivers</source>
        <translation>rimozione dei tetraedri piatti</translation>
    </message>
    <message>
        <source>checking the region volumes</source>
        <translation>verifica dei volumi delle regioni</translation>
    </message>
    <message>
        <source>measuring the mesh quality</source>
        <translation>misura della qualità della mesh</translation>
    </message>
    <message>
        <source>mesh done</source>
        <translation>mesh completata</translation>
    </message>
    <message>
        <source>tissue layers</source>
        <translation>strati di tessuto</translation>
    </message>
    <message>
        <source>texturing</source>
        <translation>applicazione della texture</translation>
    </message>
    <message>
        <source>synthesizing the texture</source>
        <translation>sintesi della texture</translation>
    </message>
    <message>
        <source>growing the vessels</source>
        <translation>crescita dei vasi</translation>
    </message>
    <message>
        <source>unfolding the surface</source>
        <translation>svolgimento della superficie</translation>
    </message>
    <message>
        <source>baking the maps</source>
        <translation>calcolo delle mappe</translation>
    </message>
    <message>
        <source>refining the surface for close-ups</source>
        <translation>raffinamento della superficie per i primi piani</translation>
    </message>
    <message>
        <source>binding the surface to the mesh</source>
        <translation>collegamento della superficie alla mesh</translation>
    </message>
    <message>
        <source>assembling the scene</source>
        <translation>assemblaggio della scena</translation>
    </message>
    <message>
        <source>distending the cavity</source>
        <translation>distensione della cavità</translation>
    </message>
    <message>
        <source>writing the package</source>
        <translation>scrittura del pacchetto</translation>
    </message>
    <message>
        <source>voxelizing the cavity for the scope</source>
        <translation>voxelizzazione della cavità per l’isteroscopio</translation>
    </message>
    <message>
        <source>measuring the room for the scope</source>
        <translation>misura dello spazio per l’isteroscopio</translation>
    </message>
    <message>
        <source>sweeping the scope&apos;s route</source>
        <translation>percorso dell’isteroscopio</translation>
    </message>
    <message>
        <source>done</source>
        <translation>fatto</translation>
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
        <translation>Miometrio</translation>
    </message>
    <message>
        <source>Endometrium</source>
        <translation>Endometrio</translation>
    </message>
    <message>
        <source>Cervix</source>
        <translation>Cervice</translation>
    </message>
    <message>
        <source>Myoma</source>
        <translation>Mioma</translation>
    </message>
    <message>
        <source>Polyp</source>
        <translation>Polipo</translation>
    </message>
    <message>
        <source>Young&apos;s modulus (kPa)</source>
        <translation>Modulo di Young (kPa)</translation>
    </message>
    <message>
        <source>Poisson ratio</source>
        <translation>Coefficiente di Poisson</translation>
    </message>
    <message>
        <source>Density (kg/m³)</source>
        <translation>Densità (kg/m³)</translation>
    </message>
    <message>
        <source>Material</source>
        <translation>Materiale</translation>
    </message>
    <message>
        <source>Default material</source>
        <translation>Materiale predefinito</translation>
    </message>
    <message>
        <source> kPa</source>
        <translation> kPa</translation>
    </message>
    <message>
        <source>Distension pressure the scene&apos;s hydrometra curve is computed for, %1 (8 kPa = 60 mmHg)</source>
        <translation>Pressione di distensione per cui viene calcolata la curva di idrometra della scena, %1 (8 kPa = 60 mmHg)</translation>
    </message>
    <message>
        <source>&amp;Hydrometra pressure</source>
        <translation>Pressione dell&apos;&amp;idrometra</translation>
    </message>
    <message>
        <source>Hydrometra pressure</source>
        <translation>Pressione dell&apos;idrometra</translation>
    </message>
    <message>
        <source>Defaults: myometrium 30 kPa, endometrium 26.2 kPa (proliferative), myoma 65 kPa, polyp 15 kPa; Poisson ratio 0.47; 1050 kg/m³ (see docs/scene-format.md).</source>
        <translation>Valori predefiniti: miometrio 30 kPa, endometrio 26,2 kPa (fase proliferativa), mioma 65 kPa, polipo 15 kPa; coefficiente di Poisson 0,47; 1050 kg/m³ (vedi docs/scene-format.md).</translation>
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
        <translation>CV di E</translation>
    </message>
    <message>
        <source>Heterogeneity: the coefficient of variation of Young&apos;s modulus per tetrahedron</source>
        <translation>Eterogeneità: il coefficiente di variazione del modulo di Young per tetraedro</translation>
    </message>
    <message>
        <source>%1: default %2; allowed %3</source>
        <translation>%1: predefinito %2; consentito %3</translation>
    </message>
    <message>
        <source>Default: use the literature values for this tissue</source>
        <translation>Predefinito: usare i valori della letteratura per questo tessuto</translation>
    </message>
    <message>
        <source>Default values for %1</source>
        <translation>Valori predefiniti per %1</translation>
    </message>
</context>
<context>
    <name>hs::widgets::MeshPanel</name>
    <message>
        <source>tets</source>
        <translation>tetraedri</translation>
    </message>
    <message>
        <source>Meshing</source>
        <translation>Generazione della mesh</translation>
    </message>
    <message>
        <source>Particles (Sierra et al. 2004)</source>
        <translation>Particelle (Sierra et al. 2004)</translation>
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
        <translation>Il generatore di mesh a particelle è il metodo dell&apos;articolo; TetGen e CGAL sono i riferimenti di confronto</translation>
    </message>
    <message>
        <source>Vertices the mesh aims at: %1</source>
        <translation>Numero di vertici a cui punta la mesh: %1</translation>
    </message>
    <message>
        <source>&amp;Target vertices</source>
        <translation>&amp;Vertici obiettivo</translation>
    </message>
    <message>
        <source>Lattice</source>
        <translation>Reticolo</translation>
    </message>
    <message>
        <source>Random, 2 per voxel</source>
        <translation>Casuale, 2 per voxel</translation>
    </message>
    <message>
        <source>How particles are seeded inside the body (particle method)</source>
        <translation>Come le particelle vengono distribuite inizialmente nel corpo (metodo a particelle)</translation>
    </message>
    <message>
        <source>&amp;Seeding</source>
        <translation>Distribuzione &amp;iniziale</translation>
    </message>
    <message>
        <source>Most relaxation iterations (%1); relaxation also stops when it converges</source>
        <translation>Numero massimo di iterazioni di rilassamento (%1); il rilassamento si ferma anche quando converge</translation>
    </message>
    <message>
        <source>&amp;Relaxation</source>
        <translation>&amp;Rilassamento</translation>
    </message>
    <message>
        <source>&amp;Mesh</source>
        <translation>&amp;Genera mesh</translation>
    </message>
    <message>
        <source>Mesh the merged body and split the wall into its tissues (Ctrl+M)</source>
        <translation>Genera la mesh del corpo unito e suddividi la parete nei suoi tessuti (Ctrl+M)</translation>
    </message>
    <message>
        <source>Meshing method</source>
        <translation>Metodo di generazione della mesh</translation>
    </message>
    <message>
        <source>Target vertices</source>
        <translation>Vertici obiettivo</translation>
    </message>
    <message>
        <source>Seeding</source>
        <translation>Distribuzione iniziale</translation>
    </message>
    <message>
        <source>Relaxation iterations</source>
        <translation>Iterazioni di rilassamento</translation>
    </message>
    <message>
        <source>Quality</source>
        <translation>Qualità</translation>
    </message>
    <message>
        <source>Not meshed yet.</source>
        <translation>Mesh non ancora generata.</translation>
    </message>
    <message>
        <source>Radius ratio</source>
        <translation>Rapporto dei raggi</translation>
    </message>
    <message>
        <source>3 × inradius / circumradius: 1 for the regular tetrahedron</source>
        <translation>3 × raggio inscritto / raggio circoscritto: 1 per il tetraedro regolare</translation>
    </message>
    <message>
        <source>Smallest dihedral angle</source>
        <translation>Angolo diedro minimo</translation>
    </message>
    <message>
        <source>Degrees; below 10° a tet is a sliver</source>
        <translation>Gradi; sotto 10° un tetraedro è uno sliver (tetraedro appiattito)</translation>
    </message>
    <message>
        <source>Colour by</source>
        <translation>Colora per</translation>
    </message>
    <message>
        <source>Tissue</source>
        <translation>Tessuto</translation>
    </message>
    <message>
        <source>Smallest dihedral</source>
        <translation>Angolo diedro minimo</translation>
    </message>
    <message>
        <source>Blue: poor, red: good (radius ratio 0 – 1, dihedral 0 – 70.5°)</source>
        <translation>Blu: scarso, rosso: buono (rapporto dei raggi 0 – 1, angolo diedro 0 – 70,5°)</translation>
    </message>
    <message>
        <source>Regions shown</source>
        <translation>Regioni visualizzate</translation>
    </message>
    <message>
        <source>Tet</source>
        <translation>Tetraedro</translation>
    </message>
    <message>
        <source>Region</source>
        <translation>Regione</translation>
    </message>
    <message>
        <source>Dihedral</source>
        <translation>Angolo diedro</translation>
    </message>
    <message>
        <source>The worst tets by radius ratio; double-click or Show frames one in the view</source>
        <translation>I tetraedri peggiori per rapporto dei raggi; doppio clic o «Mostra» ne inquadra uno nella vista</translation>
    </message>
    <message>
        <source>&amp;Show</source>
        <translation>Mo&amp;stra</translation>
    </message>
    <message>
        <source>%1 vertices, %2 tets. Radius ratio: min %3, mean %4. Smallest dihedral %5°, %6 slivers. Boundary within %7 mm of the body; volume error %8 %.</source>
        <translation>%1 vertici, %2 tetraedri. Rapporto dei raggi: min %3, media %4. Angolo diedro minimo %5°, %6 sliver. Bordo entro %7 mm dal corpo; errore di volume %8 %.</translation>
    </message>
    <message>
        <source>Inspecting the mesh</source>
        <translation>Ispezione della mesh</translation>
    </message>
    <message>
        <source>radius ratio</source>
        <translation>rapporto dei raggi</translation>
    </message>
    <message>
        <source>Me&amp;thod</source>
        <translation>Me&amp;todo</translation>
    </message>
    <message>
        <source>smallest dihedral (°)</source>
        <translation>angolo diedro minimo (°)</translation>
    </message>
</context>
<context>
    <name>hs::widgets::PathologyPanel</name>
    <message>
        <source>0 – pedunculated, intracavitary</source>
        <translation>0 – peduncolato, intracavitario</translation>
    </message>
    <message>
        <source>1 – submucosal, &lt; 50 % intramural</source>
        <translation>1 – sottomucoso, &lt; 50 % intramurale</translation>
    </message>
    <message>
        <source>2 – submucosal, ≥ 50 % intramural</source>
        <translation>2 – sottomucoso, ≥ 50 % intramurale</translation>
    </message>
    <message>
        <source>3 – intramural, touching the endometrium</source>
        <translation>3 – intramurale, a contatto con l&apos;endometrio</translation>
    </message>
    <message>
        <source>4 – intramural</source>
        <translation>4 – intramurale</translation>
    </message>
    <message>
        <source>5 – subserosal, ≥ 50 % intramural</source>
        <translation>5 – sottosieroso, ≥ 50 % intramurale</translation>
    </message>
    <message>
        <source>6 – subserosal, &lt; 50 % intramural</source>
        <translation>6 – sottosieroso, &lt; 50 % intramurale</translation>
    </message>
    <message>
        <source>7 – subserosal, pedunculated</source>
        <translation>7 – sottosieroso, peduncolato</translation>
    </message>
    <message>
        <source>1-5 – hybrid, submucosal and subserosal</source>
        <translation>1-5 – ibrido, sottomucoso e sottosieroso</translation>
    </message>
    <message>
        <source>2-5 – hybrid, submucosal and subserosal</source>
        <translation>2-5 – ibrido, sottomucoso e sottosieroso</translation>
    </message>
    <message>
        <source>3-5 – hybrid, intramural and subserosal</source>
        <translation>3-5 – ibrido, intramurale e sottosieroso</translation>
    </message>
    <message>
        <source>Anterior wall</source>
        <translation>Parete anteriore</translation>
    </message>
    <message>
        <source>Posterior wall</source>
        <translation>Parete posteriore</translation>
    </message>
    <message>
        <source>Left lateral wall</source>
        <translation>Parete laterale sinistra</translation>
    </message>
    <message>
        <source>Right lateral wall</source>
        <translation>Parete laterale destra</translation>
    </message>
    <message>
        <source>Left cornu</source>
        <translation>Corno uterino sinistro</translation>
    </message>
    <message>
        <source>Right cornu</source>
        <translation>Corno uterino destro</translation>
    </message>
    <message>
        <source>Isthmus</source>
        <translation>Istmo</translation>
    </message>
    <message>
        <source>Myoma</source>
        <translation>Mioma</translation>
    </message>
    <message>
        <source>Polyp</source>
        <translation>Polipo</translation>
    </message>
    <message>
        <source>Add &amp;Myoma</source>
        <translation>Aggiungi &amp;mioma</translation>
    </message>
    <message>
        <source>Add a 20 mm FIGO 2 myoma at a free wall</source>
        <translation>Aggiungi un mioma FIGO 2 da 20 mm su una parete libera</translation>
    </message>
    <message>
        <source>Add &amp;Polyp</source>
        <translation>Aggiungi &amp;polipo</translation>
    </message>
    <message>
        <source>Add a 10 mm sessile polyp at a free wall</source>
        <translation>Aggiungi un polipo sessile da 10 mm su una parete libera</translation>
    </message>
    <message>
        <source>D&amp;uplicate</source>
        <translation>Dup&amp;lica</translation>
    </message>
    <message>
        <source>Copy the selected pathology to a free wall</source>
        <translation>Copia la patologia selezionata su una parete libera</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Rimuovi</translation>
    </message>
    <message>
        <source>Selected pathology</source>
        <translation>Patologia selezionata</translation>
    </message>
    <message>
        <source>Names the pathology&apos;s region and files in the scene</source>
        <translation>Dà il nome alla regione e ai file della patologia nella scena</translation>
    </message>
    <message>
        <source>&amp;Id</source>
        <translation>I&amp;D</translation>
    </message>
    <message>
        <source>&amp;Kind</source>
        <translation>&amp;Tipo</translation>
    </message>
    <message>
        <source>Cellular automaton</source>
        <translation>Automa cellulare</translation>
    </message>
    <message>
        <source>Skeleton and contours</source>
        <translation>Scheletro e contorni</translation>
    </message>
    <message>
        <source>Particles</source>
        <translation>Particelle</translation>
    </message>
    <message>
        <source>How the pathology grows (Sierra et al. 2004); the automaton grows myomas only</source>
        <translation>Come cresce la patologia (Sierra et al. 2004); l&apos;automa fa crescere solo i miomi</translation>
    </message>
    <message>
        <source>FIGO type: how deep the myoma sits in the wall (myomas only)</source>
        <translation>Tipo FIGO: quanto in profondità si trova il mioma nella parete (solo miomi)</translation>
    </message>
    <message>
        <source>&amp;FIGO type</source>
        <translation>Tipo &amp;FIGO</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Largest diameter in mm (a pedunculated polyp: of its head). Myomas 5 – 100 mm, polyps 3 – 40 mm</source>
        <translation>Diametro massimo in mm (per un polipo peduncolato: quello della testa). Miomi 5 – 100 mm, polipi 3 – 40 mm</translation>
    </message>
    <message>
        <source>Si&amp;ze</source>
        <translation>Dimen&amp;sione</translation>
    </message>
    <message>
        <source>Sessile</source>
        <translation>Sessile</translation>
    </message>
    <message>
        <source>Pedunculated</source>
        <translation>Peduncolato</translation>
    </message>
    <message>
        <source>&amp;Attachment</source>
        <translation>&amp;Inserzione</translation>
    </message>
    <message>
        <source>Stalk length in mm, %1 (pedunculated polyps)</source>
        <translation>Lunghezza del peduncolo in mm, %1 (polipi peduncolati)</translation>
    </message>
    <message>
        <source>S&amp;talk</source>
        <translation>Ped&amp;uncolo</translation>
    </message>
    <message>
        <source>Placement</source>
        <translation>Posizionamento</translation>
    </message>
    <message>
        <source>At a point</source>
        <translation>In un punto</translation>
    </message>
    <message>
        <source>Click on Wall</source>
        <translation>Clic sulla parete</translation>
    </message>
    <message>
        <source>Then click on the organ&apos;s wall in the 3-D view to seat the pathology there (Ctrl+P; Esc cancels)</source>
        <translation>Poi fai clic sulla parete dell&apos;organo nella vista 3D per collocarvi la patologia (Ctrl+P; Esc annulla)</translation>
    </message>
    <message>
        <source>Grown</source>
        <translation>Crescita</translation>
    </message>
    <message>
        <source>&amp;Grow</source>
        <translation>Fai cr&amp;escere</translation>
    </message>
    <message>
        <source>Grow every pathology in the organ (Ctrl+G)</source>
        <translation>Fai crescere tutte le patologie dell&apos;organo (Ctrl+G)</translation>
    </message>
    <message>
        <source>M&amp;erge</source>
        <translation>U&amp;nisci</translation>
    </message>
    <message>
        <source>Merge the organ and the pathologies into one body with contact labels</source>
        <translation>Unisci l&apos;organo e le patologie in un unico corpo con etichette di contatto</translation>
    </message>
    <message>
        <source>Pathology id</source>
        <translation>ID della patologia</translation>
    </message>
    <message>
        <source>Pathology kind</source>
        <translation>Tipo di patologia</translation>
    </message>
    <message>
        <source>Growth model</source>
        <translation>Modello di crescita</translation>
    </message>
    <message>
        <source>FIGO type</source>
        <translation>Tipo FIGO</translation>
    </message>
    <message>
        <source>Pathology size</source>
        <translation>Dimensione della patologia</translation>
    </message>
    <message>
        <source>Polyp attachment</source>
        <translation>Inserzione del polipo</translation>
    </message>
    <message>
        <source>Stalk length</source>
        <translation>Lunghezza del peduncolo</translation>
    </message>
    <message>
        <source>The organ is still being built: click again once it is shown.</source>
        <translation>L&apos;organo è ancora in costruzione: fai di nuovo clic quando viene visualizzato.</translation>
    </message>
    <message>
        <source>Nothing placed: the click missed the organ. Click on its wall.</source>
        <translation>Nulla posizionato: il clic non ha colpito l&apos;organo. Fai clic sulla sua parete.</translation>
    </message>
    <message>
        <source>Nothing placed: that is the cervix, where pathologies are not modelled.</source>
        <translation>Nulla posizionato: è la cervice, dove le patologie non vengono modellate.</translation>
    </message>
    <message>
        <source>Nothing placed: a polyp grows from the endometrium. Click on the cavity&apos;s wall (View &gt; Clip opens the organ).</source>
        <translation>Nulla posizionato: un polipo cresce dall&apos;endometrio. Fai clic sulla parete della cavità (Visualizza &gt; Sezione apre l&apos;organo).</translation>
    </message>
    <message>
        <source>Nothing placed: the click is not on the organ&apos;s wall.</source>
        <translation>Nulla posizionato: il clic non è sulla parete dell&apos;organo.</translation>
    </message>
    <message>
        <source>Place on wall</source>
        <translation>Posiziona sulla parete</translation>
    </message>
    <message>
        <source>A case holds at most %1 pathologies.</source>
        <translation>Un caso contiene al massimo %1 patologie.</translation>
    </message>
    <message>
        <source>Add myoma</source>
        <translation>Aggiungi mioma</translation>
    </message>
    <message>
        <source>Add polyp</source>
        <translation>Aggiungi polipo</translation>
    </message>
    <message>
        <source>Duplicate pathology</source>
        <translation>Duplica patologia</translation>
    </message>
    <message>
        <source>Remove pathology</source>
        <translation>Rimuovi patologia</translation>
    </message>
    <message>
        <source>(%1, %2, %3) mm</source>
        <translation>(%1; %2; %3) mm</translation>
    </message>
    <message>
        <source>Not grown yet.</source>
        <translation>Crescita non ancora eseguita.</translation>
    </message>
    <message>
        <source>Measured: FIGO &lt;b&gt;%1&lt;/b&gt;, %2 mm, %3 % in the wall, %4 % in the cavity</source>
        <translation>Misurato: FIGO &lt;b&gt;%1&lt;/b&gt;, %2 mm, %3 % nella parete, %4 % nella cavità</translation>
    </message>
    <message>
        <source>Lasmar score &lt;b&gt;%1&lt;/b&gt; (size %2, topography %3, extension %4, penetration %5, wall %6)</source>
        <translation>Punteggio di Lasmar &lt;b&gt;%1&lt;/b&gt; (dimensione %2, topografia %3, estensione %4, penetrazione %5, parete %6)</translation>
    </message>
    <message>
        <source>Measured: a %1 mm head on a %2 mm stalk</source>
        <translation>Misurato: testa di %1 mm su un peduncolo di %2 mm</translation>
    </message>
    <message>
        <source>Measured: sessile, %1 mm, base %2 mm</source>
        <translation>Misurato: sessile, %1 mm, base %2 mm</translation>
    </message>
    <message>
        <source>From before the last edit: grow again.</source>
        <translation>Precedente all&apos;ultima modifica: ripeti la crescita.</translation>
    </message>
    <message>
        <source>Fundus</source>
        <translation>Fondo</translation>
    </message>
    <message>
        <source>Gro&amp;wth model</source>
        <translation>Modello di cresci&amp;ta</translation>
    </message>
    <message>
        <source>Site</source>
        <translation>Sede</translation>
    </message>
    <message>
        <source>measured FIGO %1</source>
        <translation>FIGO misurato %1</translation>
    </message>
    <message>
        <source>On the final body: FIGO &lt;b&gt;%1&lt;/b&gt;</source>
        <translation>Sul corpo finale: FIGO &lt;b&gt;%1&lt;/b&gt;</translation>
    </message>
    <message>
        <source>Requested FIGO %1, measured FIGO %2: the trainee meets another type than the case asks for.</source>
        <translation>FIGO %1 richiesto, FIGO %2 misurato: chi si esercita incontra un altro tipo rispetto al caso.</translation>
    </message>
    <message numerus="yes">
        <source>%n note(s) from the stage:</source>
        <translation>
            <numerusform>%n nota della fase:</numerusform>
            <numerusform>%n note della fase:</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>hs::widgets::PatientPanel</name>
    <message>
        <source>Uterine length</source>
        <translation>Lunghezza uterina</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Larghezza</translation>
    </message>
    <message>
        <source>AP depth</source>
        <translation>Profondità AP</translation>
    </message>
    <message>
        <source>Cavity length</source>
        <translation>Lunghezza della cavità</translation>
    </message>
    <message>
        <source>Cavity width</source>
        <translation>Larghezza della cavità</translation>
    </message>
    <message>
        <source>Cervix length</source>
        <translation>Lunghezza della cervice</translation>
    </message>
    <message>
        <source>Patient</source>
        <translation>Paziente</translation>
    </message>
    <message>
        <source> years</source>
        <translation> anni</translation>
    </message>
    <message>
        <source>Age in years</source>
        <translation>Età in anni</translation>
    </message>
    <message>
        <source>&amp;Age</source>
        <translation>&amp;Età</translation>
    </message>
    <message>
        <source>years</source>
        <translation>anni</translation>
    </message>
    <message>
        <source>Births after 20 weeks of gestation</source>
        <translation>Parti dopo 20 settimane di gestazione</translation>
    </message>
    <message>
        <source>&amp;Parity</source>
        <translation>Pa&amp;rità</translation>
    </message>
    <message>
        <source>births</source>
        <translation>parti</translation>
    </message>
    <message>
        <source>Pregnancies, including those that ended in a birth (at least the parity)</source>
        <translation>Gravidanze, comprese quelle terminate con un parto (almeno pari alla parità)</translation>
    </message>
    <message>
        <source>&amp;Gravidity</source>
        <translation>&amp;Gravidanze</translation>
    </message>
    <message>
        <source>pregnancies</source>
        <translation>gravidanze</translation>
    </message>
    <message>
        <source> cm</source>
        <translation> cm</translation>
    </message>
    <message>
        <source>Height in centimetres</source>
        <translation>Altezza in centimetri</translation>
    </message>
    <message>
        <source>&amp;Height</source>
        <translation>&amp;Altezza</translation>
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
        <translation>Peso in chilogrammi</translation>
    </message>
    <message>
        <source>&amp;Weight</source>
        <translation>&amp;Peso</translation>
    </message>
    <message>
        <source>kg</source>
        <translation>kg</translation>
    </message>
    <message>
        <source>Postmenopausal</source>
        <translation>In postmenopausa</translation>
    </message>
    <message>
        <source>Postmenopausal patients are 40 years or older; premenopausal ones at most 60</source>
        <translation>Le pazienti in postmenopausa hanno 40 anni o più; quelle in premenopausa al massimo 60</translation>
    </message>
    <message>
        <source>Menstrual</source>
        <translation>Mestruale</translation>
    </message>
    <message>
        <source>Proliferative</source>
        <translation>Proliferativa</translation>
    </message>
    <message>
        <source>Secretory</source>
        <translation>Secretiva</translation>
    </message>
    <message>
        <source>Phase of the cycle on the day of the hysteroscopy; it sets the endometrium&apos;s thickness (premenopausal patients only)</source>
        <translation>Fase del ciclo il giorno dell&apos;isteroscopia; determina lo spessore dell&apos;endometrio (solo pazienti in premenopausa)</translation>
    </message>
    <message>
        <source>C&amp;ycle phase</source>
        <translation>&amp;Fase del ciclo</translation>
    </message>
    <message>
        <source>Sample for this patient</source>
        <translation>Campione per questa paziente</translation>
    </message>
    <message>
        <source>Mean for this patient</source>
        <translation>Media per questa paziente</translation>
    </message>
    <message>
        <source>A seeded organ of the statistical shape model, or the model&apos;s mean for the patient</source>
        <translation>Un organo del modello statistico di forma generato dal seme, oppure la media del modello per la paziente</translation>
    </message>
    <message>
        <source>&amp;Organ</source>
        <translation>&amp;Organo</translation>
    </message>
    <message>
        <source>Every random choice of every stage derives from the seed: the same seed gives the same scene</source>
        <translation>Ogni scelta casuale di ogni fase deriva dal seme: lo stesso seme produce la stessa scena</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Nuovo</translation>
    </message>
    <message>
        <source>Draw a new seed: a new patient of the same description</source>
        <translation>Estrai un nuovo seme: una nuova paziente con la stessa descrizione</translation>
    </message>
    <message>
        <source>&amp;Seed</source>
        <translation>&amp;Seme</translation>
    </message>
    <message>
        <source>Dimensions</source>
        <translation>Dimensioni</translation>
    </message>
    <message>
        <source>Set a dimension to a measured value (ultrasound) and the organ is fitted to it</source>
        <translation>Imposta una dimensione su un valore misurato (ecografia) e l&apos;organo viene adattato</translation>
    </message>
    <message>
        <source>This organ</source>
        <translation>Questo organo</translation>
    </message>
    <message>
        <source>Expected (95 %)</source>
        <translation>Atteso (95 %)</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>Misurato</translation>
    </message>
    <message>
        <source>The published relations for this patient, mean ± 1.96 SD</source>
        <translation>Le relazioni pubblicate per questa paziente, media ± 1,96 DS</translation>
    </message>
    <message>
        <source>Fit the organ to a measured value</source>
        <translation>Adatta l&apos;organo a un valore misurato</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Allowed: %1</source>
        <translation>Consentito: %1</translation>
    </message>
    <message>
        <source>Age</source>
        <translation>Età</translation>
    </message>
    <message>
        <source>Parity</source>
        <translation>Parità</translation>
    </message>
    <message>
        <source>Gravidity</source>
        <translation>Gravidanze</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Altezza</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Peso</translation>
    </message>
    <message>
        <source>Menopausal state</source>
        <translation>Stato menopausale</translation>
    </message>
    <message>
        <source>Cycle phase</source>
        <translation>Fase del ciclo</translation>
    </message>
    <message>
        <source>Organ mode</source>
        <translation>Modalità organo</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Seme</translation>
    </message>
    <message>
        <source>New seed</source>
        <translation>Nuovo seme</translation>
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
        <translation>Fuori dall&apos;intervallo atteso per questa paziente</translation>
    </message>
    <message>
        <source>Fundal wall thickness</source>
        <translation>Spessore della parete fundica</translation>
    </message>
    <message>
        <source>(outside)</source>
        <translation>(fuori intervallo)</translation>
    </message>
</context>
<context>
    <name>hs::widgets::ReviewPanel</name>
    <message>
        <source>cellular automaton</source>
        <translation>automa cellulare</translation>
    </message>
    <message>
        <source>skeleton</source>
        <translation>scheletro</translation>
    </message>
    <message>
        <source>particles</source>
        <translation>particelle</translation>
    </message>
    <message>
        <source>–</source>
        <translation>–</translation>
    </message>
    <message>
        <source>1: not realistic … 5: indistinguishable from a real one; – not rated</source>
        <translation>1: non realistico … 5: indistinguibile da uno reale; – non valutato</translation>
    </message>
    <message>
        <source>No package opened for review (File &gt; Review Scene Package).</source>
        <translation>Nessun pacchetto aperto per la valutazione (File &gt; Valuta pacchetto di scena).</translation>
    </message>
    <message>
        <source>Reviewer</source>
        <translation>Valutatore</translation>
    </message>
    <message>
        <source>Pathologies</source>
        <translation>Patologie</translation>
    </message>
    <message>
        <source>Id</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>Growth</source>
        <translation>Crescita</translation>
    </message>
    <message>
        <source>Realism</source>
        <translation>Realismo</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Commento</translation>
    </message>
    <message>
        <source>Textures</source>
        <translation>Texture</translation>
    </message>
    <message>
        <source>Appearance</source>
        <translation>Aspetto</translation>
    </message>
    <message>
        <source>Save &amp;Review</source>
        <translation>&amp;Salva valutazione</translation>
    </message>
    <message>
        <source>Write the ratings beside the package (the package itself is not changed)</source>
        <translation>Scrivi i punteggi accanto al pacchetto (il pacchetto stesso non viene modificato)</translation>
    </message>
    <message>
        <source>All reviews in this folder</source>
        <translation>Tutte le valutazioni in questa cartella</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Gruppo</translation>
    </message>
    <message>
        <source>Ratings</source>
        <translation>Punteggi</translation>
    </message>
    <message>
        <source>Mean</source>
        <translation>Media</translation>
    </message>
    <message>
        <source>Lowest</source>
        <translation>Minimo</translation>
    </message>
    <message>
        <source>Highest</source>
        <translation>Massimo</translation>
    </message>
    <message>
        <source>Reviewing %1 (read-only)</source>
        <translation>Valutazione di %1 (sola lettura)</translation>
    </message>
    <message>
        <source>myoma</source>
        <translation>mioma</translation>
    </message>
    <message>
        <source>polyp</source>
        <translation>polipo</translation>
    </message>
    <message>
        <source>Visit</source>
        <translation>Osserva</translation>
    </message>
    <message>
        <source>Look at this pathology from inside the cavity</source>
        <translation>Osserva questa patologia dall&apos;interno della cavità</translation>
    </message>
    <message>
        <source>The pathology %1 is not a region of this scene.</source>
        <translation>La patologia %1 non è una regione di questa scena.</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;The review could not be written beside the package (is the folder read-only?).&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;Impossibile scrivere la valutazione accanto al pacchetto (la cartella è di sola lettura?).&lt;/span&gt;</translation>
    </message>
    <message>
        <source>Saved to %1.</source>
        <translation>Salvato in %1.</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;The review %1 is of another package (manifest SHA-256 %2…, this package&apos;s %3…): it is not loaded. Saving keeps it as %4.&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;La valutazione %1 riguarda un altro pacchetto (SHA-256 del manifest %2…, di questo pacchetto %3…): non viene caricata. Il salvataggio la conserva come %4.&lt;/span&gt;</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;The review %1 cannot be read: it is not loaded. Saving keeps it as %2.&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;La valutazione %1 non è leggibile: non viene caricata. Il salvataggio la conserva come %2.&lt;/span&gt;</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;The review of another package, %1, could not be moved to %2: nothing was saved.&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;La valutazione di un altro pacchetto, %1, non ha potuto essere spostata in %2: nulla è stato salvato.&lt;/span&gt;</translation>
    </message>
    <message>
        <source>endometrium</source>
        <translation>endometrio</translation>
    </message>
    <message>
        <source>texture / %1</source>
        <translation>texture / %1</translation>
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
        <translation>Organo (modello di forma)</translation>
    </message>
    <message>
        <source>Growth</source>
        <translation>Crescita</translation>
    </message>
    <message>
        <source>Displaced organ</source>
        <translation>Organo dislocato</translation>
    </message>
    <message>
        <source>%1 (grown)</source>
        <translation>%1 (cresciuto)</translation>
    </message>
    <message>
        <source>Merged body</source>
        <translation>Corpo unito</translation>
    </message>
    <message>
        <source>Wall</source>
        <translation>Parete</translation>
    </message>
    <message>
        <source>%1 (merged)</source>
        <translation>%1 (unito)</translation>
    </message>
    <message>
        <source>Tetrahedral mesh</source>
        <translation>Mesh tetraedrica</translation>
    </message>
    <message>
        <source>Visual surface (textured)</source>
        <translation>Superficie visiva (con texture)</translation>
    </message>
    <message>
        <source>Simulation mesh</source>
        <translation>Mesh di simulazione</translation>
    </message>
    <message>
        <source>Part</source>
        <translation>Parte</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation>Opacità</translation>
    </message>
    <message>
        <source>What the 3-D view shows: tick a part to show it, set its opacity to see inside it</source>
        <translation>Ciò che mostra la vista 3D: spunta una parte per mostrarla, abbassa l’opacità per vedere all’interno</translation>
    </message>
    <message>
        <source>Opacity of %1: lower it to see the parts inside</source>
        <translation>Opacità di %1: abbassala per vedere le parti all’interno</translation>
    </message>
    <message>
        <source>Opacity of %1</source>
        <translation>Opacità di %1</translation>
    </message>
    <message>
        <source>%1 — out of date</source>
        <translation>%1 — non aggiornato</translation>
    </message>
    <message>
        <source>The case has changed since this stage ran: what it shows is not the case as it is now, until the stage reruns</source>
        <translation>Il caso è cambiato da quando questa fase è stata eseguita: ciò che mostra non è il caso attuale, finché la fase non viene rieseguita</translation>
    </message>
</context>
<context>
    <name>hs::widgets::SceneWarnings</name>
    <message>
        <source>The texture stage substituted or left out part of the look: the surface may not look as the case describes.</source>
        <translation>La fase di texture ha sostituito o omesso parte dell&apos;aspetto: la superficie potrebbe non apparire come descrive il caso.</translation>
    </message>
    <message>
        <source>A pathology could not be placed or grown exactly as asked (moved off a tubal ostium or another pathology, or grown to another size or type): look at it in the 3-D view.</source>
        <translation>Una patologia non è stata posizionata o cresciuta esattamente come richiesto (spostata da un ostio tubarico o da un&apos;altra patologia, o cresciuta con altra dimensione o altro tipo): osservarla nella vista 3D.</translation>
    </message>
    <message>
        <source>Joining the pathologies to the organ changed or dropped part of one: check where they meet.</source>
        <translation>L&apos;unione delle patologie all&apos;organo ne ha modificato o eliminato una parte: controllare dove si toccano.</translation>
    </message>
    <message>
        <source>The mesher repaired or approximated part of the body: the mesh may differ from the shape it was made from.</source>
        <translation>Il generatore di mesh ha riparato o approssimato parte del corpo: la mesh può differire dalla forma di partenza.</translation>
    </message>
    <message>
        <source>A measured FIGO type, Lasmar score or size differs from the one the case asks for: the trainee meets another grade than intended.</source>
        <translation>Un tipo FIGO, un punteggio di Lasmar o una dimensione misurati differiscono da quelli del caso: chi si esercita incontra un altro grado rispetto al previsto.</translation>
    </message>
    <message>
        <source>A clinical measurement fell back to an approximation: the reported figures are less certain.</source>
        <translation>Una misura clinica è ricorsa a un&apos;approssimazione: i valori riportati sono meno certi.</translation>
    </message>
    <message>
        <source>A polyp lies against the wall over more of its surface than its kind allows: it may look buried in the wall rather than standing in the cavity.</source>
        <translation>Un polipo poggia sulla parete con una parte della superficie maggiore di quanto il suo tipo consenta: può sembrare sepolto nella parete invece che sporgere nella cavità.</translation>
    </message>
    <message>
        <source>The cavity&apos;s opening under the distension pressure was estimated from the organ without its pathologies: distension in the simulator is approximate.</source>
        <translation>L&apos;apertura della cavità sotto la pressione di distensione è stata stimata sull&apos;organo senza le sue patologie: la distensione nel simulatore è approssimata.</translation>
    </message>
    <message>
        <source>Part of the visible surface is bound away from the simulation mesh: it may drift off the tissue when the tissue moves.</source>
        <translation>Parte della superficie visibile è legata lontano dalla mesh di simulazione: può staccarsi dal tessuto quando il tessuto si muove.</translation>
    </message>
    <message>
        <source>The tetrahedral mesh misses one of its quality bars: the simulation may be less accurate or less stable where the bad elements are.</source>
        <translation>La mesh tetraedrica non rispetta una delle sue soglie di qualità: la simulazione può essere meno accurata o meno stabile dove si trovano gli elementi scadenti.</translation>
    </message>
    <message>
        <source>See the scene package&apos;s documentation (docs/scene-format.md) for this warning.</source>
        <translation>Per questo avviso vedere la documentazione del pacchetto di scena (docs/scene-format.md).</translation>
    </message>
</context>
<context>
    <name>hs::widgets::TexturePanel</name>
    <message>
        <source>Endometrium</source>
        <translation>Endometrio</translation>
    </message>
    <message>
        <source>Myoma</source>
        <translation>Mioma</translation>
    </message>
    <message>
        <source>Polyp</source>
        <translation>Polipo</translation>
    </message>
    <message>
        <source>Texture</source>
        <translation>Texture</translation>
    </message>
    <message>
        <source>%1 × %1 px</source>
        <translation>%1 × %1 px</translation>
    </message>
    <message>
        <source>Side of each square map in pixels</source>
        <translation>Lato di ogni mappa quadrata in pixel</translation>
    </message>
    <message>
        <source>Map &amp;size</source>
        <translation>&amp;Dimensione mappe</translation>
    </message>
    <message>
        <source>Vessels relative to the default network, %1; 0: none</source>
        <translation>Vasi rispetto alla rete predefinita, %1; 0: nessuno</translation>
    </message>
    <message>
        <source>&amp;Vessel density</source>
        <translation>Densità &amp;vascolare</translation>
    </message>
    <message>
        <source>Choose...</source>
        <translation>Scegli...</translation>
    </message>
    <message>
        <source>Bundled</source>
        <translation>Incluso</translation>
    </message>
    <message>
        <source>Use the bundled procedural exemplar</source>
        <translation>Usa l&apos;esempio procedurale incluso</translation>
    </message>
    <message>
        <source>Bundled exemplar</source>
        <translation>Esempio incluso</translation>
    </message>
    <message>
        <source>&amp;Texture</source>
        <translation>&amp;Texturizza</translation>
    </message>
    <message>
        <source>Synthesize and bake the maps on the final surface (Ctrl+T)</source>
        <translation>Sintetizza le mappe ed eseguine il bake sulla superficie finale (Ctrl+T)</translation>
    </message>
    <message>
        <source>Maps</source>
        <translation>Mappe</translation>
    </message>
    <message>
        <source>Albedo</source>
        <translation>Albedo</translation>
    </message>
    <message>
        <source>Normal</source>
        <translation>Normali</translation>
    </message>
    <message>
        <source>Roughness</source>
        <translation>Rugosità</translation>
    </message>
    <message>
        <source>Zoom in</source>
        <translation>Ingrandisci</translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation>Riduci</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Adatta</translation>
    </message>
    <message>
        <source>Map size</source>
        <translation>Dimensione mappe</translation>
    </message>
    <message>
        <source>Vessel density</source>
        <translation>Densità vascolare</translation>
    </message>
    <message>
        <source>The file %1 does not exist.</source>
        <translation>Il file %1 non esiste.</translation>
    </message>
    <message>
        <source>The image %1 is too small or too large: each side must be %2 – %3 px.</source>
        <translation>L&apos;immagine %1 è troppo piccola o troppo grande: ogni lato deve misurare %2 – %3 px.</translation>
    </message>
    <message>
        <source>The file %1 is not an image this program reads (PNG, JPEG, EXR, TIFF).</source>
        <translation>Il file %1 non è un&apos;immagine che questo programma legge (PNG, JPEG, EXR, TIFF).</translation>
    </message>
    <message>
        <source>Exemplar image</source>
        <translation>Immagine di esempio</translation>
    </message>
    <message>
        <source>The bundled procedural exemplar</source>
        <translation>L&apos;esempio procedurale incluso</translation>
    </message>
    <message>
        <source>Use your own image (PNG, JPEG, EXR, TIFF; %1 – %2 px a side): a crop of a real hysteroscopic view</source>
        <translation>Usare un&apos;immagine propria (PNG, JPEG, EXR, TIFF; %1 – %2 px per lato): un ritaglio di una vista isteroscopica reale</translation>
    </message>
    <message>
        <source>Cervical canal</source>
        <translation>Canale cervicale</translation>
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
        <translation>Esplorazione</translation>
    </message>
    <message>
        <source>Diagnosis</source>
        <translation>Diagnosi</translation>
    </message>
    <message>
        <source>Polypectomy</source>
        <translation>Polipectomia</translation>
    </message>
    <message>
        <source>Myomectomy</source>
        <translation>Miomectomia</translation>
    </message>
    <message>
        <source>&amp;Metrics</source>
        <translation>&amp;Misure</translation>
    </message>
    <message>
        <source>&amp;Over Time</source>
        <translation>&amp;Nel tempo</translation>
    </message>
    <message>
        <source>&amp;Visualized Surface</source>
        <translation>&amp;Superficie visualizzata</translation>
    </message>
    <message>
        <source>%1 trial, %2</source>
        <translation>Prova %1, %2</translation>
    </message>
    <message>
        <source>Scene %1, seed %2, %3° optic, %4 mm scope; device %5; physics %6.</source>
        <translation>Scena %1, seme %2, ottica %3°, isteroscopio da %4 mm; dispositivo %5; fisica %6.</translation>
    </message>
    <message>
        <source>Started %1 (UTC).</source>
        <translation>Iniziata %1 (UTC).</translation>
    </message>
    <message>
        <source>Report: %1</source>
        <translation>Rapporto: %1</translation>
    </message>
    <message>
        <source>Open the trial&apos;s scene package for review (File &gt; Review Scene Package) to see its organ beside the report.</source>
        <translation>Aprire il pacchetto di scena della prova per la revisione (File &gt; Rivedi pacchetto di scena) per vederne l&apos;organo accanto al rapporto.</translation>
    </message>
    <message>
        <source>This trial ran on the scene under review.</source>
        <translation>Questa prova si è svolta sulla scena in revisione.</translation>
    </message>
    <message>
        <source>This trial ran on another scene than the one under review (%1, not %2).</source>
        <translation>Questa prova si è svolta su un&apos;altra scena rispetto a quella in revisione (%1, non %2).</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>tempo (s)</translation>
    </message>
    <message>
        <source>Cavity surface, unrolled about the canal&apos;s axis</source>
        <translation>Superficie della cavità, srotolata attorno all&apos;asse del canale</translation>
    </message>
    <message>
        <source>seen</source>
        <translation>vista</translation>
    </message>
    <message>
        <source>not seen</source>
        <translation>non vista</translation>
    </message>
    <message>
        <source>around the axis (degrees; 0 anterior, +90 the patient&apos;s left)</source>
        <translation>attorno all&apos;asse (gradi; 0 anteriore, +90 a sinistra della paziente)</translation>
    </message>
    <message>
        <source>from the internal os (mm)</source>
        <translation>dall&apos;orifizio uterino interno (mm)</translation>
    </message>
    <message>
        <source>&amp;Replay in the Simulator...</source>
        <translation>&amp;Riproduci nel simulatore...</translation>
    </message>
    <message>
        <source>Play the recorded trial again in the simulator, on its scene package.</source>
        <translation>Riproduce la prova registrata nel simulatore, sul suo pacchetto di scena.</translation>
    </message>
    <message>
        <source>No recorded trial (%1.trial) beside the report: the simulator writes one with the report when a trial ends.</source>
        <translation>Nessuna prova registrata (%1.trial) accanto al rapporto: il simulatore la scrive con il rapporto alla fine di una prova.</translation>
    </message>
</context>
<context>
    <name>hs::widgets::VariantsView</name>
    <message>
        <source>How far every scope&apos;s tip is beyond its external os (mm)</source>
        <translation>Quanto la punta di ogni isteroscopio è oltre l&apos;orifizio uterino esterno (mm)</translation>
    </message>
    <message>
        <source>&amp;Insertion</source>
        <translation>&amp;Inserimento</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>&amp;Optic</source>
        <translation>&amp;Ottica</translation>
    </message>
    <message>
        <source>&amp;Roll</source>
        <translation>&amp;Rotazione</translation>
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
    <message>
        <source>Review Scene Package</source>
        <translation>Valuta pacchetto di scena</translation>
    </message>
    <message>
        <source>The scene package cannot be read: a file is missing, changed or breaks its format (see the details).</source>
        <translation>Impossibile leggere il pacchetto di scena: un file manca, è stato modificato o non rispetta il suo formato (vedi i dettagli).</translation>
    </message>
    <message>
        <source>Open an exported scene package read-only and rate how real it looks</source>
        <translation>Apri un pacchetto di scena esportato in sola lettura e valuta quanto sembra reale</translation>
    </message>
    <message>
        <source>Close Re&amp;view</source>
        <translation>Chiu&amp;di valutazione</translation>
    </message>
    <message>
        <source>&amp;Panels</source>
        <translation>&amp;Pannelli</translation>
    </message>
    <message>
        <source>Patient</source>
        <translation>Paziente</translation>
    </message>
    <message>
        <source>Pathologies</source>
        <translation>Patologie</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Materiali</translation>
    </message>
    <message>
        <source>Mesh</source>
        <translation>Mesh</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Esportazione</translation>
    </message>
    <message>
        <source>Texture</source>
        <translation>Texture</translation>
    </message>
    <message>
        <source>Review</source>
        <translation>Valutazione</translation>
    </message>
    <message>
        <source>Hysteroscopic View</source>
        <translation>Vista isteroscopica</translation>
    </message>
    <message>
        <source>Exemplar Image</source>
        <translation>Immagine di esempio</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.exr *.tif *.tiff)</source>
        <translation>Immagini (*.png *.jpg *.jpeg *.exr *.tif *.tiff)</translation>
    </message>
    <message>
        <source>Export Scene Package</source>
        <translation>Esporta pacchetto di scena</translation>
    </message>
    <message>
        <source>Reading the scene package</source>
        <translation>Lettura del pacchetto di scena</translation>
    </message>
    <message>
        <source>Unsaved Ratings</source>
        <translation>Punteggi non salvati</translation>
    </message>
    <message>
        <source>The review of %1 has unsaved ratings. Save them?</source>
        <translation>La valutazione di %1 ha punteggi non salvati. Salvarli?</translation>
    </message>
    <message>
        <source>Organ</source>
        <translation>Organo</translation>
    </message>
    <message>
        <source>Grown pathologies</source>
        <translation>Patologie dopo la crescita</translation>
    </message>
    <message>
        <source>Merged body</source>
        <translation>Corpo unito</translation>
    </message>
    <message>
        <source>Tetrahedral mesh</source>
        <translation>Mesh tetraedrica</translation>
    </message>
    <message>
        <source>Textured surface</source>
        <translation>Superficie con texture</translation>
    </message>
    <message>
        <source>The case&apos;s %1, as the pipeline made it</source>
        <translation>%1 del caso, risultato della pipeline</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Hysteroscene %1&lt;/h3&gt;&lt;p&gt;A scenario authoring workstation for hysteroscopy training simulators.&lt;/p&gt;&lt;p&gt;Licensed under the GNU General Public License, version 3 or later.&lt;/p&gt;&lt;p&gt;&lt;small&gt;Built with %2.&lt;/small&gt;&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Hysteroscene %1&lt;/h3&gt;&lt;p&gt;Una postazione per la creazione di scenari per simulatori di addestramento all&apos;isteroscopia.&lt;/p&gt;&lt;p&gt;Distribuito con licenza GNU General Public License, versione 3 o successiva.&lt;/p&gt;&lt;p&gt;&lt;small&gt;Compilato con %2.&lt;/small&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Revie&amp;w Scene Package...</source>
        <translation>&amp;Valuta pacchetto di scena...</translation>
    </message>
    <message>
        <source>The folder holds no scene package (no manifest.json).</source>
        <translation>La cartella non contiene alcun pacchetto di scena (nessun manifest.json).</translation>
    </message>
    <message>
        <source>Compare &amp;Variants...</source>
        <translation>Confronta &amp;varianti...</translation>
    </message>
    <message>
        <source>Show the variants of a case side by side, as the scope sees them</source>
        <translation>Mostrare affiancate le varianti di un caso, come le vede l&apos;isteroscopio</translation>
    </message>
    <message>
        <source>Compare Variants</source>
        <translation>Confronta varianti</translation>
    </message>
    <message>
        <source>Reading the variants</source>
        <translation>Lettura delle varianti</translation>
    </message>
    <message>
        <source>Variants - %1</source>
        <translation>Varianti - %1</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Annulla: %1</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Ripeti: %1</translation>
    </message>
    <message>
        <source>&amp;Stages</source>
        <translation>&amp;Fasi</translation>
    </message>
    <message>
        <source>&amp;Place on the Wall</source>
        <translation>&amp;Posiziona sulla parete</translation>
    </message>
    <message>
        <source>&amp;Grow</source>
        <translation>&amp;Fai crescere</translation>
    </message>
    <message>
        <source>&amp;Mesh</source>
        <translation>&amp;Genera la mesh</translation>
    </message>
    <message>
        <source>&amp;Texture</source>
        <translation>&amp;Applica la texture</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Esporta</translation>
    </message>
    <message>
        <source>Cancel Placing</source>
        <translation>Annulla il posizionamento</translation>
    </message>
    <message>
        <source>&amp;Orientation Marker</source>
        <translation>Indicatore di &amp;orientamento</translation>
    </message>
    <message>
        <source>Show the patient&apos;s directions in the corner of the 3-D view</source>
        <translation>Mostrare le direzioni della paziente nell&apos;angolo della vista 3D</translation>
    </message>
    <message>
        <source>&amp;Anterior</source>
        <translation>&amp;Anteriore</translation>
    </message>
    <message>
        <source>Look at the organ from in front of the patient</source>
        <translation>Guardare l&apos;organo dal davanti della paziente</translation>
    </message>
    <message>
        <source>&amp;Posterior</source>
        <translation>&amp;Posteriore</translation>
    </message>
    <message>
        <source>Look at the organ from behind the patient</source>
        <translation>Guardare l&apos;organo da dietro la paziente</translation>
    </message>
    <message>
        <source>&amp;Left</source>
        <translation>&amp;Sinistra</translation>
    </message>
    <message>
        <source>Look at the organ from the patient&apos;s left</source>
        <translation>Guardare l&apos;organo dal lato sinistro della paziente</translation>
    </message>
    <message>
        <source>&amp;Right</source>
        <translation>&amp;Destra</translation>
    </message>
    <message>
        <source>Look at the organ from the patient&apos;s right</source>
        <translation>Guardare l&apos;organo dal lato destro della paziente</translation>
    </message>
    <message>
        <source>&amp;Fundal</source>
        <translation>&amp;Fundico</translation>
    </message>
    <message>
        <source>Look down the uterine axis from above the fundus</source>
        <translation>Guardare lungo l&apos;asse uterino da sopra il fondo</translation>
    </message>
    <message>
        <source>From the External &amp;Os</source>
        <translation>Dall&apos;&amp;orifizio esterno</translation>
    </message>
    <message>
        <source>Look up the cervical canal from the external os, as the scope enters</source>
        <translation>Guardare su per il canale cervicale dall&apos;orifizio esterno, come entra l&apos;isteroscopio</translation>
    </message>
    <message>
        <source>Look &amp;From</source>
        <translation>&amp;Vista da</translation>
    </message>
    <message>
        <source>Views</source>
        <translation>Viste</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Scena</translation>
    </message>
    <message>
        <source>Out of date: the case has changed since this scene was made.</source>
        <translation>Non aggiornato: il caso è cambiato da quando questa scena è stata creata.</translation>
    </message>
    <message>
        <source>on %1</source>
        <translation>su %1</translation>
    </message>
    <message>
        <source>Out of date (%1): the case has changed since this view was made. It is remade when its stage runs again.</source>
        <translation>Non aggiornato (%1): il caso è cambiato da quando questa vista è stata creata. Verrà rifatta quando la sua fase verrà rieseguita.</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Apri</translation>
    </message>
    <message>
        <source>A scene package is being reviewed, read-only: close the review (File &gt; Close Review) before opening %1.</source>
        <translation>Un pacchetto di scena è in valutazione, in sola lettura: chiudi la valutazione (File &gt; Chiudi valutazione) prima di aprire %1.</translation>
    </message>
    <message>
        <source>The folder %1 holds no scene package (no manifest.json).</source>
        <translation>La cartella %1 non contiene alcun pacchetto di scena (nessun manifest.json).</translation>
    </message>
    <message>
        <source>%1 is not a file this program opens: it opens cases (.json), scene packages (a folder with a manifest.json) and meshes (%2).</source>
        <translation>%1 non è un file che questo programma apre: apre casi (.json), pacchetti di scena (una cartella con un manifest.json) e mesh (%2).</translation>
    </message>
    <message>
        <source>Package Changed on Disk</source>
        <translation>Pacchetto modificato sul disco</translation>
    </message>
    <message>
        <source>The scene package %1 has changed on disk since it was opened for review. Reload it? The ratings stay with the version you opened.</source>
        <translation>Il pacchetto di scena %1 è cambiato sul disco da quando è stato aperto per la valutazione. Ricaricarlo? Le valutazioni restano legate alla versione aperta.</translation>
    </message>
    <message>
        <source>The package has changed on disk since it was opened: what is shown, and rated, is the version opened.</source>
        <translation>Il pacchetto è cambiato sul disco da quando è stato aperto: ciò che è mostrato e valutato è la versione aperta.</translation>
    </message>
    <message>
        <source>The case %1 has changed on disk, and you have unsaved changes. Reload it from disk? Your changes are lost.</source>
        <translation>Il caso %1 è cambiato sul disco e hai modifiche non salvate. Ricaricarlo dal disco? Le tue modifiche andranno perse.</translation>
    </message>
    <message>
        <source>The case %1 has changed on disk. Reload it?</source>
        <translation>Il caso %1 è cambiato sul disco. Ricaricarlo?</translation>
    </message>
    <message>
        <source>Case Changed on Disk</source>
        <translation>Caso modificato sul disco</translation>
    </message>
    <message>
        <source>The case on disk differs from the one open; Save writes this one over it.</source>
        <translation>Il caso sul disco differisce da quello aperto; Salva scrive questo al suo posto.</translation>
    </message>
    <message>
        <source>The case file %1 is gone from disk; Save writes it again.</source>
        <translation>Il file del caso %1 non è più sul disco; Salva lo riscrive.</translation>
    </message>
    <message>
        <source>Review Trial Report</source>
        <translation>Rivedi rapporto della prova</translation>
    </message>
    <message>
        <source>The trial report cannot be read: it is missing or breaks its format (see the details).</source>
        <translation>Il rapporto della prova non può essere letto: manca o viola il suo formato (vedere i dettagli).</translation>
    </message>
    <message>
        <source>Review Trial Re&amp;port...</source>
        <translation>Rivedi ra&amp;pporto della prova...</translation>
    </message>
    <message>
        <source>Show a simulator trial&apos;s metrics and plots from its report</source>
        <translation>Mostrare le misure e i grafici di una prova del simulatore dal suo rapporto</translation>
    </message>
    <message>
        <source>Trial reports (*.json);;All files (*)</source>
        <translation>Rapporti delle prove (*.json);;Tutti i file (*)</translation>
    </message>
    <message>
        <source>Reading the trial report</source>
        <translation>Lettura del rapporto della prova</translation>
    </message>
    <message>
        <source>Trial Report - %1</source>
        <translation>Rapporto della prova - %1</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>Riproduzione</translation>
    </message>
    <message>
        <source>The simulator is not installed beside the workstation.</source>
        <translation>Il simulatore non è installato accanto alla workstation.</translation>
    </message>
    <message>
        <source>No executable %1.</source>
        <translation>Nessun eseguibile %1.</translation>
    </message>
    <message>
        <source>The Scene Package the Trial Ran On</source>
        <translation>Il pacchetto di scena della prova</translation>
    </message>
    <message>
        <source>The simulator did not start.</source>
        <translation>Il simulatore non si è avviato.</translation>
    </message>
    <message>
        <source>Replaying %1 in the simulator.</source>
        <translation>Riproduzione di %1 nel simulatore.</translation>
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
    <message>
        <source>A case file (.json) to author, a scene package (a folder) or a simulator&apos;s trial report (.json) to review, or a surface or tetrahedral mesh to open.</source>
        <translation>Un file di caso (.json) da modificare, un pacchetto di scena (una cartella) o un rapporto di prova del simulatore (.json) da rivedere, oppure una superficie o una mesh tetraedrica da aprire.</translation>
    </message>
</context>
</TS>
