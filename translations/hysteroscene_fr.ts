<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr">
<context>
    <name>hs::simapp::SimWindow</name>
    <message>
        <source>&amp;Polypectomy: resect the polyps with the loop</source>
        <translation>&amp;Polypectomie : réséquer les polypes à l&apos;anse</translation>
    </message>
    <message>
        <source>&amp;Myomectomy: resect the submucous myomas with the loop</source>
        <translation>&amp;Myomectomie : réséquer les myomes sous-muqueux à l&apos;anse</translation>
    </message>
    <message>
        <source>This device speaks version 1 of the hysteroscope protocol: it drives the diagnostic scope only. The resectoscope&apos;s loop, pedals and pump buttons need a device of version 2 (docs/haptics-protocol.md); without one the %1 exercise cannot cut.</source>
        <translation>Cet appareil parle la version 1 du protocole de l&apos;hystéroscope : il ne pilote que l&apos;hystéroscope diagnostique. L&apos;anse, les pédales et les boutons de pompe du résectoscope demandent un appareil de version 2 (docs/haptics-protocol.md) ; sans lui, l&apos;exercice %1 ne peut pas couper.</translation>
    </message>
    <message>
        <source>&lt;p&gt;The instruments (polypectomy, myomectomy) and the pump:&lt;/p&gt;&lt;table&gt;&lt;tr&gt;&lt;td&gt;L&lt;/td&gt;&lt;td&gt;the next instrument: the resectoscope&apos;s loop, scissors, grasper, none&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;R / F&lt;/td&gt;&lt;td&gt;push the instrument out / draw it in (the working element)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;C, held&lt;/td&gt;&lt;td&gt;the cutting pedal (scissors and grasper: close the jaws)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;V, held&lt;/td&gt;&lt;td&gt;the coagulating pedal&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;+ / -&lt;/td&gt;&lt;td&gt;raise / lower the pump&apos;s set pressure by 5 mmHg&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;p&gt;Les instruments (polypectomie, myomectomie) et la pompe :&lt;/p&gt;&lt;table&gt;&lt;tr&gt;&lt;td&gt;L&lt;/td&gt;&lt;td&gt;l&apos;instrument suivant : l&apos;anse du résectoscope, ciseaux, pince à préhension, aucun&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;R / F&lt;/td&gt;&lt;td&gt;sortir / rentrer l&apos;instrument (l&apos;élément de travail)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;C, maintenue&lt;/td&gt;&lt;td&gt;la pédale de coupe (ciseaux et pince : fermer les mors)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;V, maintenue&lt;/td&gt;&lt;td&gt;la pédale de coagulation&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;+ / -&lt;/td&gt;&lt;td&gt;augmenter / baisser la pression de consigne de la pompe de 5 mmHg&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
    <message>
        <source>hysteroscene simulator</source>
        <translation>Simulateur hysteroscene</translation>
    </message>
    <message>
        <source>Open a scene package (File &gt; Open).</source>
        <translation>Ouvrez un paquet de scène (Fichier &gt; Ouvrir un paquet).</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <source>&amp;Open Package...</source>
        <translation>&amp;Ouvrir un paquet...</translation>
    </message>
    <message>
        <source>&amp;End Trial and Show Report...</source>
        <translation>&amp;Terminer l&apos;essai et afficher le rapport...</translation>
    </message>
    <message>
        <source>&amp;Restart Trial</source>
        <translation>&amp;Recommencer l&apos;essai</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <source>&amp;Scope</source>
        <translation>&amp;Hystéroscope</translation>
    </message>
    <message>
        <source>&amp;Optic</source>
        <translation>&amp;Optique</translation>
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
        <translation>&amp;Diamètre</translation>
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
        <translation>&amp;Exercice</translation>
    </message>
    <message>
        <source>&amp;Exploration: see the fundus, both ostia and every wall</source>
        <translation>&amp;Exploration : voir le fond utérin, les deux ostia tubaires et chaque paroi</translation>
    </message>
    <message>
        <source>&amp;Diagnosis: mark each pathology</source>
        <translation>&amp;Diagnostic : marquer chaque pathologie</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>A&amp;ide</translation>
    </message>
    <message>
        <source>&amp;Keys...</source>
        <translation>&amp;Touches...</translation>
    </message>
    <message>
        <source>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Arrow keys, or drag with the mouse&lt;/td&gt;&lt;td&gt;turn the scope about the cervix (pitch, yaw)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;W / S, or the mouse wheel&lt;/td&gt;&lt;td&gt;insert / withdraw&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Q / E&lt;/td&gt;&lt;td&gt;roll the scope (an oblique optic looks round)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Z / X&lt;/td&gt;&lt;td&gt;roll the camera head (the image&apos;s horizon)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;I / O&lt;/td&gt;&lt;td&gt;open or close the inflow / outflow valve&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Space&lt;/td&gt;&lt;td&gt;mark the pathology at the centre of the view&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Ctrl+E&lt;/td&gt;&lt;td&gt;end the trial and show the report&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Ctrl+R&lt;/td&gt;&lt;td&gt;restart the trial&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;F1&lt;/td&gt;&lt;td&gt;this help&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</source>
        <translation>&lt;table&gt;&lt;tr&gt;&lt;td&gt;Touches fléchées, ou glisser avec la souris&lt;/td&gt;&lt;td&gt;orienter l&apos;hystéroscope autour du col utérin (haut/bas, gauche/droite)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;W / S, ou la molette de la souris&lt;/td&gt;&lt;td&gt;introduire / retirer&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Q / E&lt;/td&gt;&lt;td&gt;tourner l&apos;hystéroscope sur son axe (une optique foroblique regarde sur le côté)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Z / X&lt;/td&gt;&lt;td&gt;tourner la tête de caméra (l&apos;horizon de l&apos;image)&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;I / O&lt;/td&gt;&lt;td&gt;ouvrir ou fermer la valve d&apos;entrée / de sortie&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Espace&lt;/td&gt;&lt;td&gt;marquer la pathologie au centre de la vue&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Ctrl+E&lt;/td&gt;&lt;td&gt;terminer l&apos;essai et afficher le rapport&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Ctrl+R&lt;/td&gt;&lt;td&gt;recommencer l&apos;essai&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;F1&lt;/td&gt;&lt;td&gt;cette aide&lt;/td&gt;&lt;/tr&gt;&lt;/table&gt;</translation>
    </message>
    <message>
        <source>Keys</source>
        <translation>Touches</translation>
    </message>
    <message>
        <source>Loading %1...</source>
        <translation>Chargement de %1...</translation>
    </message>
    <message>
        <source>The package could not be loaded.</source>
        <translation>Le paquet n&apos;a pas pu être chargé.</translation>
    </message>
    <message>
        <source>Open Package</source>
        <translation>Ouvrir un paquet</translation>
    </message>
    <message>
        <source>The scene package could not be loaded.</source>
        <translation>Le paquet de scène n&apos;a pas pu être chargé.</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>Relecture</translation>
    </message>
    <message>
        <source>The trial could not be read.</source>
        <translation>L&apos;enregistrement de l&apos;essai n&apos;a pas pu être lu.</translation>
    </message>
    <message>
        <source>Script</source>
        <translation>Script</translation>
    </message>
    <message>
        <source>The script could not be read.</source>
        <translation>Le script n&apos;a pas pu être lu.</translation>
    </message>
    <message>
        <source>Haptic device</source>
        <translation>Dispositif haptique</translation>
    </message>
    <message>
        <source>The haptic hysteroscope could not be opened.</source>
        <translation>L&apos;hystéroscope haptique n&apos;a pas pu être ouvert.</translation>
    </message>
    <message>
        <source>hysteroscene simulator: %1</source>
        <translation>Simulateur hysteroscene : %1</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <source>The simulation stopped.</source>
        <translation>La simulation s&apos;est arrêtée.</translation>
    </message>
    <message>
        <source>The device&apos;s samples have ended: File &gt; End Trial shows the report.</source>
        <translation>Les échantillons du dispositif sont épuisés : Fichier &gt; Terminer l&apos;essai affiche le rapport.</translation>
    </message>
    <message>
        <source>Save the Trial&apos;s Report</source>
        <translation>Enregistrer le rapport de l&apos;essai</translation>
    </message>
    <message>
        <source>Trial reports (*.json)</source>
        <translation>Rapports d&apos;essai (*.json)</translation>
    </message>
    <message>
        <source>Trial Report</source>
        <translation>Rapport de l&apos;essai</translation>
    </message>
    <message>
        <source>The report is in %1. Open it?</source>
        <translation>Le rapport est dans %1. L&apos;ouvrir ?</translation>
    </message>
    <message>
        <source>The report could not be written.</source>
        <translation>Le rapport n&apos;a pas pu être écrit.</translation>
    </message>
    <message>
        <source>Trial ended; report written to %1.</source>
        <translation>Essai terminé ; rapport écrit dans %1.</translation>
    </message>
    <message>
        <source>Open a Scene Package</source>
        <translation>Ouvrir un paquet de scène</translation>
    </message>
    <message>
        <source> (light view: software GL)</source>
        <translation> (vue allégée : GL logiciel)</translation>
    </message>
    <message>
        <source>%L1 fps%4, physics %L2 steps/s, insertion %L3 mm</source>
        <translation>%L1 i/s%4, physique %L2 pas/s, insertion %L3 mm</translation>
    </message>
    <message>
        <source>The trial was recorded with other settings.</source>
        <translation>L’essai a été enregistré avec d’autres réglages.</translation>
    </message>
    <message>
        <source>Demonstration</source>
        <translation>Démonstration</translation>
    </message>
    <message>
        <source>The demonstration could not be planned.</source>
        <translation>La démonstration n&apos;a pas pu être planifiée.</translation>
    </message>
</context>
<context>
    <name>hs::widgets</name>
    <message>
        <source>Gravidity counts every pregnancy, so it cannot be less than the parity.</source>
        <translation>La gestité compte toutes les grossesses ; elle ne peut donc pas être inférieure à la parité.</translation>
    </message>
    <message>
        <source>A postmenopausal patient is at least 40 years old, a premenopausal one at most 60.</source>
        <translation>Une patiente ménopausée a au moins 40 ans, une patiente non ménopausée au plus 60.</translation>
    </message>
    <message>
        <source>Only a premenopausal patient has a cycle phase.</source>
        <translation>Seule une patiente non ménopausée a une phase du cycle.</translation>
    </message>
    <message>
        <source>The cavity must be shorter than the uterus.</source>
        <translation>La cavité doit être plus courte que l&apos;utérus.</translation>
    </message>
    <message>
        <source>The cavity must be narrower than the uterus.</source>
        <translation>La cavité doit être plus étroite que l&apos;utérus.</translation>
    </message>
    <message>
        <source>Myomas are 5 – 100 mm, polyps 3 – 40 mm in size.</source>
        <translation>Les myomes mesurent de 5 à 100 mm, les polypes de 3 à 40 mm.</translation>
    </message>
    <message>
        <source>A case holds at most %1 pathologies.</source>
        <translation>Un cas contient au plus %1 pathologies.</translation>
    </message>
    <message>
        <source>This value is not allowed here (%1).</source>
        <translation>Cette valeur n&apos;est pas autorisée ici (%1).</translation>
    </message>
    <message>
        <source>An id is 1 – 32 letters, digits, &apos;-&apos; or &apos;_&apos;, starts with a letter or digit, and is unique in the case.</source>
        <translation>Un identifiant compte 1 – 32 lettres, chiffres, &apos;-&apos; ou &apos;_&apos;, commence par une lettre ou un chiffre et est unique dans le cas.</translation>
    </message>
    <message>
        <source>Young&apos;s modulus must be in the range %1.</source>
        <translation>Le module de Young doit être dans la plage %1.</translation>
    </message>
    <message>
        <source>The Poisson ratio must be in the range %1.</source>
        <translation>Le coefficient de Poisson doit être dans la plage %1.</translation>
    </message>
    <message>
        <source>The density must be in the range %1.</source>
        <translation>La densité doit être dans la plage %1.</translation>
    </message>
    <message>
        <source>The heterogeneity must be in the range %1.</source>
        <translation>L&apos;hétérogénéité doit être dans la plage %1.</translation>
    </message>
    <message>
        <source>The hydrometra pressure must be in the range %1.</source>
        <translation>La pression d&apos;hydromètre doit être dans la plage %1.</translation>
    </message>
    <message>
        <source>%1 must be in the range %2.</source>
        <translation>« %1 » doit être dans la plage %2.</translation>
    </message>
</context>
<context>
    <name>hs::widgets::CaseDocument</name>
    <message>
        <source>Untitled</source>
        <translation>Sans titre</translation>
    </message>
    <message>
        <source>Recover unsaved changes</source>
        <translation>Récupérer les modifications non enregistrées</translation>
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
        <translation>Âge</translation>
    </message>
    <message>
        <source>years</source>
        <translation>ans</translation>
    </message>
    <message>
        <source>Parity</source>
        <translation>Parité</translation>
    </message>
    <message>
        <source>births</source>
        <translation>accouchements</translation>
    </message>
    <message>
        <source>Gravidity</source>
        <translation>Gestité</translation>
    </message>
    <message>
        <source>pregnancies</source>
        <translation>grossesses</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Taille</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Poids</translation>
    </message>
    <message>
        <source>Uterine length</source>
        <translation>Longueur utérine</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Largeur</translation>
    </message>
    <message>
        <source>AP depth</source>
        <translation>Profondeur AP</translation>
    </message>
    <message>
        <source>Cavity length</source>
        <translation>Longueur de la cavité</translation>
    </message>
    <message>
        <source>Cavity width</source>
        <translation>Largeur de la cavité</translation>
    </message>
    <message>
        <source>Cervix length</source>
        <translation>Longueur du col utérin</translation>
    </message>
    <message>
        <source>Stalk length</source>
        <translation>Longueur du pédicule</translation>
    </message>
    <message>
        <source>Target vertices</source>
        <translation>Sommets cibles</translation>
    </message>
    <message>
        <source>Vessel density</source>
        <translation>Densité vasculaire</translation>
    </message>
    <message>
        <source>Fundal wall thickness</source>
        <translation>Épaisseur de la paroi fundique</translation>
    </message>
</context>
<context>
    <name>hs::widgets::ExportPanel</name>
    <message>
        <source>Scene package</source>
        <translation>Paquet de scène</translation>
    </message>
    <message>
        <source>Folder of the package</source>
        <translation>Dossier du paquet</translation>
    </message>
    <message>
        <source>The package is written to this folder (created; an existing package is replaced)</source>
        <translation>Le paquet est écrit dans ce dossier (créé au besoin ; un paquet existant est remplacé)</translation>
    </message>
    <message>
        <source>&amp;Browse...</source>
        <translation>&amp;Parcourir...</translation>
    </message>
    <message>
        <source>&amp;Folder</source>
        <translation>&amp;Dossier</translation>
    </message>
    <message>
        <source>Also as a .zip</source>
        <translation>Également en .zip</translation>
    </message>
    <message>
        <source>Also the formats of other tools: glTF, Gmsh MSH, OBJ, SOFA</source>
        <translation>Aussi les formats d’autres outils : glTF, Gmsh MSH, OBJ, SOFA</translation>
    </message>
    <message>
        <source>More than one: a new patient of the same description per variant, each in folder/variant-NNN with its own seed</source>
        <translation>Plus d&apos;une : une nouvelle patiente de même description par variante, chacune dans dossier/variant-NNN avec sa propre graine</translation>
    </message>
    <message>
        <source>&amp;Variants</source>
        <translation>&amp;Variantes</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exporter</translation>
    </message>
    <message>
        <source>Run what is not current, write the package and validate it (Ctrl+E)</source>
        <translation>Exécuter ce qui n&apos;est pas à jour, écrire le paquet et le valider (Ctrl+E)</translation>
    </message>
    <message>
        <source>Open in &amp;Simulator</source>
        <translation>Ouvrir dans le &amp;simulateur</translation>
    </message>
    <message>
        <source>The preview simulator is not installed with this workstation</source>
        <translation>Le simulateur d&apos;aperçu n&apos;est pas installé avec ce poste de travail</translation>
    </message>
    <message>
        <source>Start the preview simulator on the exported package</source>
        <translation>Lancer le simulateur d&apos;aperçu sur le paquet exporté</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;Choose a folder for the package first.&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;Choisissez d&apos;abord un dossier pour le paquet.&lt;/span&gt;</translation>
    </message>
    <message>
        <source>Exporting...</source>
        <translation>Exportation...</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: valid, %2 files with matching checksums (seed %3).</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; : valide, %2 fichiers aux sommes de contrôle concordantes (graine %3).</translation>
    </message>
    <message>
        <source>Zipped as %1.</source>
        <translation>Compressé en %1.</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;The simulator could not be started.&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;Le simulateur n&apos;a pas pu être lancé.&lt;/span&gt;</translation>
    </message>
    <message>
        <source>The scope&apos;s passage could not be checked: %1</source>
        <translation>Le passage de l&apos;hystéroscope n&apos;a pas pu être vérifié : %1</translation>
    </message>
    <message numerus="yes">
        <source>%n warning(s), also in scene.json:</source>
        <translation>
            <numerusform>%n avertissement, aussi dans scene.json :</numerusform>
            <numerusform>%n avertissements, aussi dans scene.json :</numerusform>
        </translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;A %1 mm scope does not pass the cervical canal (narrowest %2 mm).&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;Un hystéroscope de %1 mm ne franchit pas le canal cervical (passage le plus étroit %2 mm).&lt;/span&gt;</translation>
    </message>
    <message>
        <source>A %1 mm scope passes the cervical canal (narrowest %2 mm) and reaches the fundus (narrowest %3 mm).</source>
        <translation>Un hystéroscope de %1 mm franchit le canal cervical (passage le plus étroit %2 mm) et atteint le fond utérin (passage le plus étroit %3 mm).</translation>
    </message>
    <message>
        <source>A %1 mm scope passes the cervical canal (narrowest %2 mm); a pathology narrows the way to the fundus to %3 mm.</source>
        <translation>Un hystéroscope de %1 mm franchit le canal cervical (passage le plus étroit %2 mm) ; une pathologie rétrécit le chemin vers le fond utérin à %3 mm.</translation>
    </message>
</context>
<context>
    <name>hs::widgets::GenerationSession</name>
    <message>
        <source>Building the organ</source>
        <translation>Construction de l&apos;organe</translation>
    </message>
    <message>
        <source>Growing the pathologies</source>
        <translation>Croissance des pathologies</translation>
    </message>
    <message>
        <source>Merging the body</source>
        <translation>Fusion du corps</translation>
    </message>
    <message>
        <source>Meshing</source>
        <translation>Maillage</translation>
    </message>
    <message>
        <source>Texturing</source>
        <translation>Texturation</translation>
    </message>
    <message>
        <source>Assembling the scene</source>
        <translation>Assemblage de la scène</translation>
    </message>
    <message>
        <source>Exporting the scene</source>
        <translation>Export de la scène</translation>
    </message>
</context>
<context>
    <name>hs::widgets::HysteroscopicPreview</name>
    <message>
        <source>How far the scope&apos;s tip is beyond the external os (mm)</source>
        <translation>Distance de la pointe de l&apos;hystéroscope au-delà de l&apos;orifice externe du col (mm)</translation>
    </message>
    <message>
        <source>&amp;Insertion</source>
        <translation>&amp;Insertion</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>The optic&apos;s angle off the shaft; office scopes are typically 30°</source>
        <translation>Angle de l&apos;optique par rapport à l&apos;axe de la gaine ; les hystéroscopes de consultation ont généralement 30°</translation>
    </message>
    <message>
        <source>&amp;Optic</source>
        <translation>&amp;Optique</translation>
    </message>
    <message>
        <source>The light post&apos;s rotation about the shaft (degrees; 0 looks anterior)</source>
        <translation>Rotation du raccord de lumière autour de la gaine (degrés ; 0 regarde vers l&apos;avant)</translation>
    </message>
    <message>
        <source>&amp;Roll</source>
        <translation>&amp;Rotation</translation>
    </message>
    <message>
        <source>Texture the case to see the cavity.</source>
        <translation>Texturez le cas pour voir la cavité.</translation>
    </message>
    <message>
        <source>This scene has no cervical canal or ostium labels: the scope cannot be placed.</source>
        <translation>Cette scène n&apos;a pas d&apos;étiquettes de canal cervical ni d&apos;orifice : l&apos;hystéroscope ne peut pas être placé.</translation>
    </message>
    <message>
        <source>Tip %1 mm beyond the external os, %2 optic, roll %3°</source>
        <translation>Pointe à %1 mm au-delà de l&apos;orifice externe, optique %2, rotation %3°</translation>
    </message>
    <message>
        <source>Looking at region %1 from %2 mm inside the cavity</source>
        <translation>Vue de la région %1 à %2 mm de distance, depuis l&apos;intérieur de la cavité</translation>
    </message>
</context>
<context>
    <name>hs::widgets::JobRunner</name>
    <message>
        <source>The case asks for something the pipeline cannot make: a value is outside its allowed range or a pathology does not fit (see the details).</source>
        <translation>Le cas demande quelque chose que le pipeline ne peut pas produire : une valeur est hors de sa plage autorisée ou une pathologie n&apos;a pas la place (voir les détails).</translation>
    </message>
    <message>
        <source>A file the case names does not exist.</source>
        <translation>Un fichier désigné par le cas n&apos;existe pas.</translation>
    </message>
    <message>
        <source>A file could not be read or written.</source>
        <translation>Un fichier n&apos;a pas pu être lu ou écrit.</translation>
    </message>
    <message>
        <source>The case asks for something this version does not support.</source>
        <translation>Le cas demande quelque chose que cette version ne prend pas en charge.</translation>
    </message>
    <message>
        <source>The result would be larger than this program accepts.</source>
        <translation>Le résultat dépasserait la taille acceptée par ce programme.</translation>
    </message>
    <message>
        <source>The job was cancelled.</source>
        <translation>La tâche a été annulée.</translation>
    </message>
    <message>
        <source>A geometry or image library failed on this case.</source>
        <translation>Une bibliothèque de géométrie ou d&apos;image a échoué sur ce cas.</translation>
    </message>
    <message>
        <source>An internal error stopped the job.</source>
        <translation>Une erreur interne a arrêté la tâche.</translation>
    </message>
</context>
<context>
    <name>hs::widgets::JobStatusWidget</name>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Stop the running job (Esc)</source>
        <translation>Arrêter la tâche en cours (Esc)</translation>
    </message>
    <message>
        <source>organ from the shape model</source>
        <translation>organe issu du modèle de forme</translation>
    </message>
    <message>
        <source>pathologies</source>
        <translation>pathologies</translation>
    </message>
    <message>
        <source>growing the pathologies</source>
        <translation>croissance des pathologies</translation>
    </message>
    <message>
        <source>measuring the pathologies</source>
        <translation>mesure des pathologies</translation>
    </message>
    <message>
        <source>merging</source>
        <translation>fusion</translation>
    </message>
    <message>
        <source>joining the organ and the pathologies</source>
        <translation>réunion de l’organe et des pathologies</translation>
    </message>
    <message>
        <source>labelling the contacts</source>
        <translation>étiquetage des contacts</translation>
    </message>
    <message>
        <source>covering the pathologies</source>
        <translation>recouvrement des pathologies</translation>
    </message>
    <message>
        <source>checking the merged body</source>
        <translation>vérification du corps fusionné</translation>
    </message>
    <message>
        <source>meshing the body</source>
        <translation>maillage du corps</translation>
    </message>
    <message>
        <source>voxelizing the body</source>
        <translation>voxélisation du corps</translation>
    </message>
    <message>
        <source>seeding the particles</source>
        <translation>semis des particules</translation>
    </message>
    <message>
        <source>relaxing the particles</source>
        <translation>relaxation des particules</translation>
    </message>
    <message>
        <source>tetrahedralizing</source>
        <translation>tétraédrisation</translation>
    </message>
    <message>
        <source>removing slivers</source>
        <translation>suppression des tétraèdres plats</translation>
    </message>
    <message>
        <source>checking the region volumes</source>
        <translation>vérification des volumes des régions</translation>
    </message>
    <message>
        <source>measuring the mesh quality</source>
        <translation>mesure de la qualité du maillage</translation>
    </message>
    <message>
        <source>mesh done</source>
        <translation>maillage terminé</translation>
    </message>
    <message>
        <source>tissue layers</source>
        <translation>couches de tissu</translation>
    </message>
    <message>
        <source>texturing</source>
        <translation>texturage</translation>
    </message>
    <message>
        <source>synthesizing the texture</source>
        <translation>synthèse de la texture</translation>
    </message>
    <message>
        <source>growing the vessels</source>
        <translation>croissance des vaisseaux</translation>
    </message>
    <message>
        <source>unfolding the surface</source>
        <translation>dépliage de la surface</translation>
    </message>
    <message>
        <source>baking the maps</source>
        <translation>calcul des cartes</translation>
    </message>
    <message>
        <source>refining the surface for close-ups</source>
        <translation>affinage de la surface pour les gros plans</translation>
    </message>
    <message>
        <source>binding the surface to the mesh</source>
        <translation>liaison de la surface au maillage</translation>
    </message>
    <message>
        <source>assembling the scene</source>
        <translation>assemblage de la scène</translation>
    </message>
    <message>
        <source>distending the cavity</source>
        <translation>distension de la cavité</translation>
    </message>
    <message>
        <source>writing the package</source>
        <translation>écriture du paquet</translation>
    </message>
    <message>
        <source>voxelizing the cavity for the scope</source>
        <translation>voxélisation de la cavité pour l’hystéroscope</translation>
    </message>
    <message>
        <source>measuring the room for the scope</source>
        <translation>mesure de l’espace pour l’hystéroscope</translation>
    </message>
    <message>
        <source>sweeping the scope&apos;s route</source>
        <translation>parcours de la trajectoire de l’hystéroscope</translation>
    </message>
    <message>
        <source>done</source>
        <translation>terminé</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
</context>
<context>
    <name>hs::widgets::MaterialsPanel</name>
    <message>
        <source>Myometrium</source>
        <translation>Myomètre</translation>
    </message>
    <message>
        <source>Endometrium</source>
        <translation>Endomètre</translation>
    </message>
    <message>
        <source>Cervix</source>
        <translation>Col utérin</translation>
    </message>
    <message>
        <source>Myoma</source>
        <translation>Myome</translation>
    </message>
    <message>
        <source>Polyp</source>
        <translation>Polype</translation>
    </message>
    <message>
        <source>Young&apos;s modulus (kPa)</source>
        <translation>Module de Young (kPa)</translation>
    </message>
    <message>
        <source>Poisson ratio</source>
        <translation>Coefficient de Poisson</translation>
    </message>
    <message>
        <source>Density (kg/m³)</source>
        <translation>Masse volumique (kg/m³)</translation>
    </message>
    <message>
        <source>Material</source>
        <translation>Matériau</translation>
    </message>
    <message>
        <source>Default material</source>
        <translation>Matériau par défaut</translation>
    </message>
    <message>
        <source> kPa</source>
        <translation> kPa</translation>
    </message>
    <message>
        <source>Distension pressure the scene&apos;s hydrometra curve is computed for, %1 (8 kPa = 60 mmHg)</source>
        <translation>Pression de distension pour laquelle la courbe d&apos;hydromètre de la scène est calculée, %1 (8 kPa = 60 mmHg)</translation>
    </message>
    <message>
        <source>&amp;Hydrometra pressure</source>
        <translation>Pression d&apos;&amp;hydromètre</translation>
    </message>
    <message>
        <source>Hydrometra pressure</source>
        <translation>Pression d&apos;hydromètre</translation>
    </message>
    <message>
        <source>Defaults: myometrium 30 kPa, endometrium 26.2 kPa (proliferative), myoma 65 kPa, polyp 15 kPa; Poisson ratio 0.47; 1050 kg/m³ (see docs/scene-format.md).</source>
        <translation>Valeurs par défaut : myomètre 30 kPa, endomètre 26,2 kPa (phase proliférative), myome 65 kPa, polype 15 kPa ; coefficient de Poisson 0,47 ; 1050 kg/m³ (voir docs/scene-format.md).</translation>
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
        <translation>CV de E</translation>
    </message>
    <message>
        <source>Heterogeneity: the coefficient of variation of Young&apos;s modulus per tetrahedron</source>
        <translation>Hétérogénéité : le coefficient de variation du module de Young par tétraèdre</translation>
    </message>
    <message>
        <source>%1: default %2; allowed %3</source>
        <translation>%1 : défaut %2 ; autorisé %3</translation>
    </message>
    <message>
        <source>Default: use the literature values for this tissue</source>
        <translation>Défaut : utiliser les valeurs de la littérature pour ce tissu</translation>
    </message>
    <message>
        <source>Default values for %1</source>
        <translation>Valeurs par défaut pour %1</translation>
    </message>
</context>
<context>
    <name>hs::widgets::MeshPanel</name>
    <message>
        <source>tets</source>
        <translation>tétraèdres</translation>
    </message>
    <message>
        <source>Meshing</source>
        <translation>Maillage</translation>
    </message>
    <message>
        <source>Particles (Sierra et al. 2004)</source>
        <translation>Particules (Sierra et al. 2004)</translation>
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
        <translation>Le mailleur à particules est la méthode de l&apos;article ; TetGen et CGAL servent de référence</translation>
    </message>
    <message>
        <source>Vertices the mesh aims at: %1</source>
        <translation>Nombre de sommets visé pour le maillage : %1</translation>
    </message>
    <message>
        <source>&amp;Target vertices</source>
        <translation>Sommets &amp;cibles</translation>
    </message>
    <message>
        <source>Lattice</source>
        <translation>Grille</translation>
    </message>
    <message>
        <source>Random, 2 per voxel</source>
        <translation>Aléatoire, 2 par voxel</translation>
    </message>
    <message>
        <source>How particles are seeded inside the body (particle method)</source>
        <translation>Comment les particules sont placées initialement dans le corps (méthode à particules)</translation>
    </message>
    <message>
        <source>&amp;Seeding</source>
        <translation>Placement &amp;initial</translation>
    </message>
    <message>
        <source>Most relaxation iterations (%1); relaxation also stops when it converges</source>
        <translation>Nombre maximal d&apos;itérations de relaxation (%1) ; la relaxation s&apos;arrête aussi dès qu&apos;elle converge</translation>
    </message>
    <message>
        <source>&amp;Relaxation</source>
        <translation>&amp;Relaxation</translation>
    </message>
    <message>
        <source>&amp;Mesh</source>
        <translation>M&amp;ailler</translation>
    </message>
    <message>
        <source>Mesh the merged body and split the wall into its tissues (Ctrl+M)</source>
        <translation>Mailler le corps fusionné et séparer la paroi en ses tissus (Ctrl+M)</translation>
    </message>
    <message>
        <source>Meshing method</source>
        <translation>Méthode de maillage</translation>
    </message>
    <message>
        <source>Target vertices</source>
        <translation>Sommets cibles</translation>
    </message>
    <message>
        <source>Seeding</source>
        <translation>Placement initial</translation>
    </message>
    <message>
        <source>Relaxation iterations</source>
        <translation>Itérations de relaxation</translation>
    </message>
    <message>
        <source>Quality</source>
        <translation>Qualité</translation>
    </message>
    <message>
        <source>Not meshed yet.</source>
        <translation>Pas encore maillé.</translation>
    </message>
    <message>
        <source>Radius ratio</source>
        <translation>Rapport des rayons</translation>
    </message>
    <message>
        <source>3 × inradius / circumradius: 1 for the regular tetrahedron</source>
        <translation>3 × rayon inscrit / rayon circonscrit : 1 pour le tétraèdre régulier</translation>
    </message>
    <message>
        <source>Smallest dihedral angle</source>
        <translation>Plus petit angle dièdre</translation>
    </message>
    <message>
        <source>Degrees; below 10° a tet is a sliver</source>
        <translation>Degrés ; en dessous de 10°, un tétraèdre est un sliver (tétraèdre aplati)</translation>
    </message>
    <message>
        <source>Colour by</source>
        <translation>Colorer selon</translation>
    </message>
    <message>
        <source>Tissue</source>
        <translation>Tissu</translation>
    </message>
    <message>
        <source>Smallest dihedral</source>
        <translation>Plus petit angle dièdre</translation>
    </message>
    <message>
        <source>Blue: poor, red: good (radius ratio 0 – 1, dihedral 0 – 70.5°)</source>
        <translation>Bleu : mauvais, rouge : bon (rapport des rayons 0 – 1, angle dièdre 0 – 70,5°)</translation>
    </message>
    <message>
        <source>Regions shown</source>
        <translation>Régions affichées</translation>
    </message>
    <message>
        <source>Tet</source>
        <translation>Tétraèdre</translation>
    </message>
    <message>
        <source>Region</source>
        <translation>Région</translation>
    </message>
    <message>
        <source>Dihedral</source>
        <translation>Angle dièdre</translation>
    </message>
    <message>
        <source>The worst tets by radius ratio; double-click or Show frames one in the view</source>
        <translation>Les pires tétraèdres selon le rapport des rayons ; un double-clic ou « Afficher » en cadre un dans la vue</translation>
    </message>
    <message>
        <source>&amp;Show</source>
        <translation>A&amp;fficher</translation>
    </message>
    <message>
        <source>%1 vertices, %2 tets. Radius ratio: min %3, mean %4. Smallest dihedral %5°, %6 slivers. Boundary within %7 mm of the body; volume error %8 %.</source>
        <translation>%1 sommets, %2 tétraèdres. Rapport des rayons : min %3, moyenne %4. Plus petit angle dièdre %5°, %6 slivers. Bord à moins de %7 mm du corps ; erreur de volume %8 %.</translation>
    </message>
    <message>
        <source>Inspecting the mesh</source>
        <translation>Inspection du maillage</translation>
    </message>
    <message>
        <source>radius ratio</source>
        <translation>rapport des rayons</translation>
    </message>
    <message>
        <source>Me&amp;thod</source>
        <translation>Mé&amp;thode</translation>
    </message>
    <message>
        <source>smallest dihedral (°)</source>
        <translation>plus petit angle dièdre (°)</translation>
    </message>
</context>
<context>
    <name>hs::widgets::PathologyPanel</name>
    <message>
        <source>0 – pedunculated, intracavitary</source>
        <translation>0 – pédiculé, intracavitaire</translation>
    </message>
    <message>
        <source>1 – submucosal, &lt; 50 % intramural</source>
        <translation>1 – sous-muqueux, &lt; 50 % intramural</translation>
    </message>
    <message>
        <source>2 – submucosal, ≥ 50 % intramural</source>
        <translation>2 – sous-muqueux, ≥ 50 % intramural</translation>
    </message>
    <message>
        <source>3 – intramural, touching the endometrium</source>
        <translation>3 – intramural, au contact de l&apos;endomètre</translation>
    </message>
    <message>
        <source>4 – intramural</source>
        <translation>4 – intramural</translation>
    </message>
    <message>
        <source>5 – subserosal, ≥ 50 % intramural</source>
        <translation>5 – sous-séreux, ≥ 50 % intramural</translation>
    </message>
    <message>
        <source>6 – subserosal, &lt; 50 % intramural</source>
        <translation>6 – sous-séreux, &lt; 50 % intramural</translation>
    </message>
    <message>
        <source>7 – subserosal, pedunculated</source>
        <translation>7 – sous-séreux, pédiculé</translation>
    </message>
    <message>
        <source>1-5 – hybrid, submucosal and subserosal</source>
        <translation>1-5 – hybride, sous-muqueux et sous-séreux</translation>
    </message>
    <message>
        <source>2-5 – hybrid, submucosal and subserosal</source>
        <translation>2-5 – hybride, sous-muqueux et sous-séreux</translation>
    </message>
    <message>
        <source>3-5 – hybrid, intramural and subserosal</source>
        <translation>3-5 – hybride, intramural et sous-séreux</translation>
    </message>
    <message>
        <source>Anterior wall</source>
        <translation>Paroi antérieure</translation>
    </message>
    <message>
        <source>Posterior wall</source>
        <translation>Paroi postérieure</translation>
    </message>
    <message>
        <source>Left lateral wall</source>
        <translation>Paroi latérale gauche</translation>
    </message>
    <message>
        <source>Right lateral wall</source>
        <translation>Paroi latérale droite</translation>
    </message>
    <message>
        <source>Left cornu</source>
        <translation>Corne utérine gauche</translation>
    </message>
    <message>
        <source>Right cornu</source>
        <translation>Corne utérine droite</translation>
    </message>
    <message>
        <source>Isthmus</source>
        <translation>Isthme</translation>
    </message>
    <message>
        <source>Myoma</source>
        <translation>Myome</translation>
    </message>
    <message>
        <source>Polyp</source>
        <translation>Polype</translation>
    </message>
    <message>
        <source>Add &amp;Myoma</source>
        <translation>Ajouter un &amp;myome</translation>
    </message>
    <message>
        <source>Add a 20 mm FIGO 2 myoma at a free wall</source>
        <translation>Ajouter un myome FIGO 2 de 20 mm sur une paroi libre</translation>
    </message>
    <message>
        <source>Add &amp;Polyp</source>
        <translation>Ajouter un &amp;polype</translation>
    </message>
    <message>
        <source>Add a 10 mm sessile polyp at a free wall</source>
        <translation>Ajouter un polype sessile de 10 mm sur une paroi libre</translation>
    </message>
    <message>
        <source>D&amp;uplicate</source>
        <translation>&amp;Dupliquer</translation>
    </message>
    <message>
        <source>Copy the selected pathology to a free wall</source>
        <translation>Copier la pathologie sélectionnée sur une paroi libre</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>&amp;Supprimer</translation>
    </message>
    <message>
        <source>Selected pathology</source>
        <translation>Pathologie sélectionnée</translation>
    </message>
    <message>
        <source>Names the pathology&apos;s region and files in the scene</source>
        <translation>Nomme la région et les fichiers de la pathologie dans la scène</translation>
    </message>
    <message>
        <source>&amp;Id</source>
        <translation>&amp;Identifiant</translation>
    </message>
    <message>
        <source>&amp;Kind</source>
        <translation>&amp;Nature</translation>
    </message>
    <message>
        <source>Cellular automaton</source>
        <translation>Automate cellulaire</translation>
    </message>
    <message>
        <source>Skeleton and contours</source>
        <translation>Squelette et contours</translation>
    </message>
    <message>
        <source>Particles</source>
        <translation>Particules</translation>
    </message>
    <message>
        <source>How the pathology grows (Sierra et al. 2004); the automaton grows myomas only</source>
        <translation>Comment la pathologie croît (Sierra et al. 2004) ; l&apos;automate ne fait croître que les myomes</translation>
    </message>
    <message>
        <source>FIGO type: how deep the myoma sits in the wall (myomas only)</source>
        <translation>Type FIGO : profondeur du myome dans la paroi (myomes uniquement)</translation>
    </message>
    <message>
        <source>&amp;FIGO type</source>
        <translation>Type &amp;FIGO</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Largest diameter in mm (a pedunculated polyp: of its head). Myomas 5 – 100 mm, polyps 3 – 40 mm</source>
        <translation>Plus grand diamètre en mm (pour un polype pédiculé : celui de sa tête). Myomes 5 – 100 mm, polypes 3 – 40 mm</translation>
    </message>
    <message>
        <source>Si&amp;ze</source>
        <translation>Tai&amp;lle</translation>
    </message>
    <message>
        <source>Sessile</source>
        <translation>Sessile</translation>
    </message>
    <message>
        <source>Pedunculated</source>
        <translation>Pédiculé</translation>
    </message>
    <message>
        <source>&amp;Attachment</source>
        <translation>Implan&amp;tation</translation>
    </message>
    <message>
        <source>Stalk length in mm, %1 (pedunculated polyps)</source>
        <translation>Longueur du pédicule en mm, %1 (polypes pédiculés)</translation>
    </message>
    <message>
        <source>S&amp;talk</source>
        <translation>Pédicul&amp;e</translation>
    </message>
    <message>
        <source>Placement</source>
        <translation>Placement</translation>
    </message>
    <message>
        <source>At a point</source>
        <translation>En un point</translation>
    </message>
    <message>
        <source>Click on Wall</source>
        <translation>Cliquer sur la paroi</translation>
    </message>
    <message>
        <source>Then click on the organ&apos;s wall in the 3-D view to seat the pathology there (Ctrl+P; Esc cancels)</source>
        <translation>Puis cliquer sur la paroi de l&apos;organe dans la vue 3D pour y placer la pathologie (Ctrl+P ; Esc annule)</translation>
    </message>
    <message>
        <source>Grown</source>
        <translation>Croissance</translation>
    </message>
    <message>
        <source>&amp;Grow</source>
        <translation>Cr&amp;oître</translation>
    </message>
    <message>
        <source>Grow every pathology in the organ (Ctrl+G)</source>
        <translation>Faire croître toutes les pathologies de l&apos;organe (Ctrl+G)</translation>
    </message>
    <message>
        <source>M&amp;erge</source>
        <translation>F&amp;usionner</translation>
    </message>
    <message>
        <source>Merge the organ and the pathologies into one body with contact labels</source>
        <translation>Fusionner l&apos;organe et les pathologies en un seul corps avec des étiquettes de contact</translation>
    </message>
    <message>
        <source>Pathology id</source>
        <translation>Identifiant de la pathologie</translation>
    </message>
    <message>
        <source>Pathology kind</source>
        <translation>Nature de la pathologie</translation>
    </message>
    <message>
        <source>Growth model</source>
        <translation>Modèle de croissance</translation>
    </message>
    <message>
        <source>FIGO type</source>
        <translation>Type FIGO</translation>
    </message>
    <message>
        <source>Pathology size</source>
        <translation>Taille de la pathologie</translation>
    </message>
    <message>
        <source>Polyp attachment</source>
        <translation>Implantation du polype</translation>
    </message>
    <message>
        <source>Stalk length</source>
        <translation>Longueur du pédicule</translation>
    </message>
    <message>
        <source>The organ is still being built: click again once it is shown.</source>
        <translation>L&apos;organe est encore en construction : cliquez à nouveau dès qu&apos;il est affiché.</translation>
    </message>
    <message>
        <source>Nothing placed: the click missed the organ. Click on its wall.</source>
        <translation>Rien n&apos;a été placé : le clic n&apos;a pas touché l&apos;organe. Cliquez sur sa paroi.</translation>
    </message>
    <message>
        <source>Nothing placed: that is the cervix, where pathologies are not modelled.</source>
        <translation>Rien n&apos;a été placé : c&apos;est le col utérin, où les pathologies ne sont pas modélisées.</translation>
    </message>
    <message>
        <source>Nothing placed: a polyp grows from the endometrium. Click on the cavity&apos;s wall (View &gt; Clip opens the organ).</source>
        <translation>Rien n&apos;a été placé : un polype naît de l&apos;endomètre. Cliquez sur la paroi de la cavité (Affichage &gt; Coupe ouvre l&apos;organe).</translation>
    </message>
    <message>
        <source>Nothing placed: the click is not on the organ&apos;s wall.</source>
        <translation>Rien n&apos;a été placé : le clic n&apos;est pas sur la paroi de l&apos;organe.</translation>
    </message>
    <message>
        <source>Place on wall</source>
        <translation>Placer sur la paroi</translation>
    </message>
    <message>
        <source>A case holds at most %1 pathologies.</source>
        <translation>Un cas contient au plus %1 pathologies.</translation>
    </message>
    <message>
        <source>Add myoma</source>
        <translation>Ajouter un myome</translation>
    </message>
    <message>
        <source>Add polyp</source>
        <translation>Ajouter un polype</translation>
    </message>
    <message>
        <source>Duplicate pathology</source>
        <translation>Dupliquer la pathologie</translation>
    </message>
    <message>
        <source>Remove pathology</source>
        <translation>Supprimer la pathologie</translation>
    </message>
    <message>
        <source>(%1, %2, %3) mm</source>
        <translation>(%1 ; %2 ; %3) mm</translation>
    </message>
    <message>
        <source>Not grown yet.</source>
        <translation>Croissance pas encore effectuée.</translation>
    </message>
    <message>
        <source>Measured: FIGO &lt;b&gt;%1&lt;/b&gt;, %2 mm, %3 % in the wall, %4 % in the cavity</source>
        <translation>Mesuré : FIGO &lt;b&gt;%1&lt;/b&gt;, %2 mm, %3 % dans la paroi, %4 % dans la cavité</translation>
    </message>
    <message>
        <source>Lasmar score &lt;b&gt;%1&lt;/b&gt; (size %2, topography %3, extension %4, penetration %5, wall %6)</source>
        <translation>Score de Lasmar &lt;b&gt;%1&lt;/b&gt; (taille %2, topographie %3, extension %4, pénétration %5, paroi %6)</translation>
    </message>
    <message>
        <source>Measured: a %1 mm head on a %2 mm stalk</source>
        <translation>Mesuré : tête de %1 mm sur un pédicule de %2 mm</translation>
    </message>
    <message>
        <source>Measured: sessile, %1 mm, base %2 mm</source>
        <translation>Mesuré : sessile, %1 mm, base %2 mm</translation>
    </message>
    <message>
        <source>From before the last edit: grow again.</source>
        <translation>Antérieur à la dernière modification : relancez la croissance.</translation>
    </message>
    <message>
        <source>Fundus</source>
        <translation>Fond utérin</translation>
    </message>
    <message>
        <source>Gro&amp;wth model</source>
        <translation>&amp;Modèle de croissance</translation>
    </message>
    <message>
        <source>Site</source>
        <translation>Localisation</translation>
    </message>
    <message>
        <source>measured FIGO %1</source>
        <translation>FIGO mesuré %1</translation>
    </message>
    <message>
        <source>On the final body: FIGO &lt;b&gt;%1&lt;/b&gt;</source>
        <translation>Sur le corps final : FIGO &lt;b&gt;%1&lt;/b&gt;</translation>
    </message>
    <message>
        <source>Requested FIGO %1, measured FIGO %2: the trainee meets another type than the case asks for.</source>
        <translation>FIGO %1 demandé, FIGO %2 mesuré : l&apos;apprenant rencontre un autre type que celui du cas.</translation>
    </message>
    <message numerus="yes">
        <source>%n note(s) from the stage:</source>
        <translation>
            <numerusform>%n remarque de l&apos;étape :</numerusform>
            <numerusform>%n remarques de l&apos;étape :</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>hs::widgets::PatientPanel</name>
    <message>
        <source>Uterine length</source>
        <translation>Longueur utérine</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Largeur</translation>
    </message>
    <message>
        <source>AP depth</source>
        <translation>Profondeur AP</translation>
    </message>
    <message>
        <source>Cavity length</source>
        <translation>Longueur de la cavité</translation>
    </message>
    <message>
        <source>Cavity width</source>
        <translation>Largeur de la cavité</translation>
    </message>
    <message>
        <source>Cervix length</source>
        <translation>Longueur du col utérin</translation>
    </message>
    <message>
        <source>Patient</source>
        <translation>Patiente</translation>
    </message>
    <message>
        <source> years</source>
        <translation> ans</translation>
    </message>
    <message>
        <source>Age in years</source>
        <translation>Âge en années</translation>
    </message>
    <message>
        <source>&amp;Age</source>
        <translation>Âg&amp;e</translation>
    </message>
    <message>
        <source>years</source>
        <translation>ans</translation>
    </message>
    <message>
        <source>Births after 20 weeks of gestation</source>
        <translation>Accouchements après 20 semaines de grossesse</translation>
    </message>
    <message>
        <source>&amp;Parity</source>
        <translation>&amp;Parité</translation>
    </message>
    <message>
        <source>births</source>
        <translation>accouchements</translation>
    </message>
    <message>
        <source>Pregnancies, including those that ended in a birth (at least the parity)</source>
        <translation>Grossesses, y compris celles qui ont abouti à un accouchement (au moins la parité)</translation>
    </message>
    <message>
        <source>&amp;Gravidity</source>
        <translation>&amp;Gestité</translation>
    </message>
    <message>
        <source>pregnancies</source>
        <translation>grossesses</translation>
    </message>
    <message>
        <source> cm</source>
        <translation> cm</translation>
    </message>
    <message>
        <source>Height in centimetres</source>
        <translation>Taille en centimètres</translation>
    </message>
    <message>
        <source>&amp;Height</source>
        <translation>&amp;Taille</translation>
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
        <translation>Poids en kilogrammes</translation>
    </message>
    <message>
        <source>&amp;Weight</source>
        <translation>Poi&amp;ds</translation>
    </message>
    <message>
        <source>kg</source>
        <translation>kg</translation>
    </message>
    <message>
        <source>Postmenopausal</source>
        <translation>Ménopausée</translation>
    </message>
    <message>
        <source>Postmenopausal patients are 40 years or older; premenopausal ones at most 60</source>
        <translation>Les patientes ménopausées ont 40 ans ou plus ; les non ménopausées au plus 60</translation>
    </message>
    <message>
        <source>Menstrual</source>
        <translation>Menstruelle</translation>
    </message>
    <message>
        <source>Proliferative</source>
        <translation>Proliférative</translation>
    </message>
    <message>
        <source>Secretory</source>
        <translation>Sécrétoire</translation>
    </message>
    <message>
        <source>Phase of the cycle on the day of the hysteroscopy; it sets the endometrium&apos;s thickness (premenopausal patients only)</source>
        <translation>Phase du cycle le jour de l&apos;hystéroscopie ; elle détermine l&apos;épaisseur de l&apos;endomètre (patientes non ménopausées uniquement)</translation>
    </message>
    <message>
        <source>C&amp;ycle phase</source>
        <translation>Phase du &amp;cycle</translation>
    </message>
    <message>
        <source>Sample for this patient</source>
        <translation>Échantillon pour cette patiente</translation>
    </message>
    <message>
        <source>Mean for this patient</source>
        <translation>Moyenne pour cette patiente</translation>
    </message>
    <message>
        <source>A seeded organ of the statistical shape model, or the model&apos;s mean for the patient</source>
        <translation>Un organe du modèle statistique de forme tiré selon la graine, ou la moyenne du modèle pour la patiente</translation>
    </message>
    <message>
        <source>&amp;Organ</source>
        <translation>&amp;Organe</translation>
    </message>
    <message>
        <source>Every random choice of every stage derives from the seed: the same seed gives the same scene</source>
        <translation>Chaque choix aléatoire de chaque étape découle de la graine : la même graine donne la même scène</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Nouvelle</translation>
    </message>
    <message>
        <source>Draw a new seed: a new patient of the same description</source>
        <translation>Tirer une nouvelle graine : une nouvelle patiente de même description</translation>
    </message>
    <message>
        <source>&amp;Seed</source>
        <translation>Grai&amp;ne</translation>
    </message>
    <message>
        <source>Dimensions</source>
        <translation>Dimensions</translation>
    </message>
    <message>
        <source>Set a dimension to a measured value (ultrasound) and the organ is fitted to it</source>
        <translation>Fixez une dimension à une valeur mesurée (échographie) et l&apos;organe s&apos;y ajuste</translation>
    </message>
    <message>
        <source>This organ</source>
        <translation>Cet organe</translation>
    </message>
    <message>
        <source>Expected (95 %)</source>
        <translation>Attendu (95 %)</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>Mesuré</translation>
    </message>
    <message>
        <source>The published relations for this patient, mean ± 1.96 SD</source>
        <translation>Les relations publiées pour cette patiente, moyenne ± 1,96 ET</translation>
    </message>
    <message>
        <source>Fit the organ to a measured value</source>
        <translation>Ajuster l&apos;organe à une valeur mesurée</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Allowed: %1</source>
        <translation>Autorisé : %1</translation>
    </message>
    <message>
        <source>Age</source>
        <translation>Âge</translation>
    </message>
    <message>
        <source>Parity</source>
        <translation>Parité</translation>
    </message>
    <message>
        <source>Gravidity</source>
        <translation>Gestité</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Taille</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Poids</translation>
    </message>
    <message>
        <source>Menopausal state</source>
        <translation>Statut ménopausique</translation>
    </message>
    <message>
        <source>Cycle phase</source>
        <translation>Phase du cycle</translation>
    </message>
    <message>
        <source>Organ mode</source>
        <translation>Mode de l&apos;organe</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Graine</translation>
    </message>
    <message>
        <source>New seed</source>
        <translation>Nouvelle graine</translation>
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
        <translation>Hors de la plage attendue pour cette patiente</translation>
    </message>
    <message>
        <source>Fundal wall thickness</source>
        <translation>Épaisseur de la paroi fundique</translation>
    </message>
    <message>
        <source>(outside)</source>
        <translation>(hors plage)</translation>
    </message>
</context>
<context>
    <name>hs::widgets::ReviewPanel</name>
    <message>
        <source>cellular automaton</source>
        <translation>automate cellulaire</translation>
    </message>
    <message>
        <source>skeleton</source>
        <translation>squelette</translation>
    </message>
    <message>
        <source>particles</source>
        <translation>particules</translation>
    </message>
    <message>
        <source>–</source>
        <translation>–</translation>
    </message>
    <message>
        <source>1: not realistic … 5: indistinguishable from a real one; – not rated</source>
        <translation>1 : pas réaliste … 5 : impossible à distinguer d&apos;un vrai ; – non noté</translation>
    </message>
    <message>
        <source>No package opened for review (File &gt; Review Scene Package).</source>
        <translation>Aucun paquet ouvert pour évaluation (Fichier &gt; Évaluer un paquet de scène).</translation>
    </message>
    <message>
        <source>Reviewer</source>
        <translation>Évaluateur</translation>
    </message>
    <message>
        <source>Pathologies</source>
        <translation>Pathologies</translation>
    </message>
    <message>
        <source>Id</source>
        <translation>Identifiant</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Nature</translation>
    </message>
    <message>
        <source>Growth</source>
        <translation>Croissance</translation>
    </message>
    <message>
        <source>Realism</source>
        <translation>Réalisme</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Commentaire</translation>
    </message>
    <message>
        <source>Textures</source>
        <translation>Textures</translation>
    </message>
    <message>
        <source>Appearance</source>
        <translation>Aspect</translation>
    </message>
    <message>
        <source>Save &amp;Review</source>
        <translation>&amp;Enregistrer l&apos;évaluation</translation>
    </message>
    <message>
        <source>Write the ratings beside the package (the package itself is not changed)</source>
        <translation>Écrire les notes à côté du paquet (le paquet lui-même n&apos;est pas modifié)</translation>
    </message>
    <message>
        <source>All reviews in this folder</source>
        <translation>Toutes les évaluations de ce dossier</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Groupe</translation>
    </message>
    <message>
        <source>Ratings</source>
        <translation>Notes</translation>
    </message>
    <message>
        <source>Mean</source>
        <translation>Moyenne</translation>
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
        <translation>Évaluation de %1 (lecture seule)</translation>
    </message>
    <message>
        <source>myoma</source>
        <translation>myome</translation>
    </message>
    <message>
        <source>polyp</source>
        <translation>polype</translation>
    </message>
    <message>
        <source>Visit</source>
        <translation>Observer</translation>
    </message>
    <message>
        <source>Look at this pathology from inside the cavity</source>
        <translation>Observer cette pathologie depuis l&apos;intérieur de la cavité</translation>
    </message>
    <message>
        <source>The pathology %1 is not a region of this scene.</source>
        <translation>La pathologie %1 n&apos;est pas une région de cette scène.</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;The review could not be written beside the package (is the folder read-only?).&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;L&apos;évaluation n&apos;a pas pu être écrite à côté du paquet (le dossier est-il en lecture seule ?).&lt;/span&gt;</translation>
    </message>
    <message>
        <source>Saved to %1.</source>
        <translation>Enregistré dans %1.</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;The review %1 is of another package (manifest SHA-256 %2…, this package&apos;s %3…): it is not loaded. Saving keeps it as %4.&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;L’évaluation %1 concerne un autre paquet (SHA-256 du manifeste %2…, celui de ce paquet %3…) : elle n’est pas chargée. L’enregistrement la conserve sous %4.&lt;/span&gt;</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;The review %1 cannot be read: it is not loaded. Saving keeps it as %2.&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;L’évaluation %1 est illisible : elle n’est pas chargée. L’enregistrement la conserve sous %2.&lt;/span&gt;</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;The review of another package, %1, could not be moved to %2: nothing was saved.&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;L’évaluation d’un autre paquet, %1, n’a pas pu être déplacée vers %2 : rien n’a été enregistré.&lt;/span&gt;</translation>
    </message>
    <message>
        <source>endometrium</source>
        <translation>endomètre</translation>
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
        <translation>Organe (modèle de forme)</translation>
    </message>
    <message>
        <source>Growth</source>
        <translation>Croissance</translation>
    </message>
    <message>
        <source>Displaced organ</source>
        <translation>Organe déplacé</translation>
    </message>
    <message>
        <source>%1 (grown)</source>
        <translation>%1 (croissance)</translation>
    </message>
    <message>
        <source>Merged body</source>
        <translation>Corps fusionné</translation>
    </message>
    <message>
        <source>Wall</source>
        <translation>Paroi</translation>
    </message>
    <message>
        <source>%1 (merged)</source>
        <translation>%1 (fusionné)</translation>
    </message>
    <message>
        <source>Tetrahedral mesh</source>
        <translation>Maillage tétraédrique</translation>
    </message>
    <message>
        <source>Visual surface (textured)</source>
        <translation>Surface visuelle (texturée)</translation>
    </message>
    <message>
        <source>Simulation mesh</source>
        <translation>Maillage de simulation</translation>
    </message>
    <message>
        <source>Part</source>
        <translation>Partie</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation>Opacité</translation>
    </message>
    <message>
        <source>What the 3-D view shows: tick a part to show it, set its opacity to see inside it</source>
        <translation>Ce que montre la vue 3D : cochez une partie pour l’afficher, baissez son opacité pour voir à l’intérieur</translation>
    </message>
    <message>
        <source>Opacity of %1: lower it to see the parts inside</source>
        <translation>Opacité de %1 : baissez-la pour voir les parties à l’intérieur</translation>
    </message>
    <message>
        <source>Opacity of %1</source>
        <translation>Opacité de %1</translation>
    </message>
    <message>
        <source>%1 — out of date</source>
        <translation>%1 — périmé</translation>
    </message>
    <message>
        <source>The case has changed since this stage ran: what it shows is not the case as it is now, until the stage reruns</source>
        <translation>Le cas a changé depuis l’exécution de cette étape : ce qu’elle montre n’est pas le cas actuel, jusqu’à ce qu’elle soit relancée</translation>
    </message>
</context>
<context>
    <name>hs::widgets::SceneWarnings</name>
    <message>
        <source>The texture stage substituted or left out part of the look: the surface may not look as the case describes.</source>
        <translation>L&apos;étape de texture a remplacé ou omis une partie de l&apos;aspect : la surface peut ne pas ressembler à ce que décrit le cas.</translation>
    </message>
    <message>
        <source>A pathology could not be placed or grown exactly as asked (moved off a tubal ostium or another pathology, or grown to another size or type): look at it in the 3-D view.</source>
        <translation>Une pathologie n&apos;a pas pu être placée ou croître exactement comme demandé (écartée d&apos;un ostium tubaire ou d&apos;une autre pathologie, ou d&apos;une autre taille ou d&apos;un autre type) : examinez-la dans la vue 3D.</translation>
    </message>
    <message>
        <source>Joining the pathologies to the organ changed or dropped part of one: check where they meet.</source>
        <translation>La fusion des pathologies avec l&apos;organe a modifié ou supprimé une partie de l&apos;une d&apos;elles : vérifiez leurs zones de contact.</translation>
    </message>
    <message>
        <source>The mesher repaired or approximated part of the body: the mesh may differ from the shape it was made from.</source>
        <translation>Le mailleur a réparé ou approché une partie du corps : le maillage peut différer de la forme d&apos;origine.</translation>
    </message>
    <message>
        <source>A measured FIGO type, Lasmar score or size differs from the one the case asks for: the trainee meets another grade than intended.</source>
        <translation>Un type FIGO, un score de Lasmar ou une taille mesurés diffèrent de ceux du cas : l&apos;apprenant rencontre un autre grade que prévu.</translation>
    </message>
    <message>
        <source>A clinical measurement fell back to an approximation: the reported figures are less certain.</source>
        <translation>Une mesure clinique a dû recourir à une approximation : les valeurs rapportées sont moins sûres.</translation>
    </message>
    <message>
        <source>A polyp lies against the wall over more of its surface than its kind allows: it may look buried in the wall rather than standing in the cavity.</source>
        <translation>Un polype repose contre la paroi sur une plus grande part de sa surface que son type ne le permet : il peut sembler enfoui dans la paroi plutôt que dressé dans la cavité.</translation>
    </message>
    <message>
        <source>The cavity&apos;s opening under the distension pressure was estimated from the organ without its pathologies: distension in the simulator is approximate.</source>
        <translation>L&apos;ouverture de la cavité sous la pression de distension a été estimée sur l&apos;organe sans ses pathologies : la distension dans le simulateur est approximative.</translation>
    </message>
    <message>
        <source>Part of the visible surface is bound away from the simulation mesh: it may drift off the tissue when the tissue moves.</source>
        <translation>Une partie de la surface visible est liée à l&apos;écart du maillage de simulation : elle peut se détacher du tissu quand celui-ci bouge.</translation>
    </message>
    <message>
        <source>The tetrahedral mesh misses one of its quality bars: the simulation may be less accurate or less stable where the bad elements are.</source>
        <translation>Le maillage tétraédrique manque l&apos;un de ses seuils de qualité : la simulation peut être moins précise ou moins stable là où sont les mauvais éléments.</translation>
    </message>
    <message>
        <source>See the scene package&apos;s documentation (docs/scene-format.md) for this warning.</source>
        <translation>Pour cet avertissement, voir la documentation du paquet de scène (docs/scene-format.md).</translation>
    </message>
</context>
<context>
    <name>hs::widgets::TexturePanel</name>
    <message>
        <source>Endometrium</source>
        <translation>Endomètre</translation>
    </message>
    <message>
        <source>Myoma</source>
        <translation>Myome</translation>
    </message>
    <message>
        <source>Polyp</source>
        <translation>Polype</translation>
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
        <translation>Côté de chaque carte carrée en pixels</translation>
    </message>
    <message>
        <source>Map &amp;size</source>
        <translation>Taille des &amp;cartes</translation>
    </message>
    <message>
        <source>Vessels relative to the default network, %1; 0: none</source>
        <translation>Vaisseaux par rapport au réseau par défaut, %1 ; 0 : aucun</translation>
    </message>
    <message>
        <source>&amp;Vessel density</source>
        <translation>&amp;Densité vasculaire</translation>
    </message>
    <message>
        <source>Choose...</source>
        <translation>Choisir...</translation>
    </message>
    <message>
        <source>Bundled</source>
        <translation>Fourni</translation>
    </message>
    <message>
        <source>Use the bundled procedural exemplar</source>
        <translation>Utiliser l&apos;exemple procédural fourni</translation>
    </message>
    <message>
        <source>Bundled exemplar</source>
        <translation>Exemple fourni</translation>
    </message>
    <message>
        <source>&amp;Texture</source>
        <translation>&amp;Texturer</translation>
    </message>
    <message>
        <source>Synthesize and bake the maps on the final surface (Ctrl+T)</source>
        <translation>Synthétiser les cartes et les précalculer (bake) sur la surface finale (Ctrl+T)</translation>
    </message>
    <message>
        <source>Maps</source>
        <translation>Cartes</translation>
    </message>
    <message>
        <source>Albedo</source>
        <translation>Albédo</translation>
    </message>
    <message>
        <source>Normal</source>
        <translation>Normales</translation>
    </message>
    <message>
        <source>Roughness</source>
        <translation>Rugosité</translation>
    </message>
    <message>
        <source>Zoom in</source>
        <translation>Zoom avant</translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation>Zoom arrière</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Ajuster</translation>
    </message>
    <message>
        <source>Map size</source>
        <translation>Taille des cartes</translation>
    </message>
    <message>
        <source>Vessel density</source>
        <translation>Densité vasculaire</translation>
    </message>
    <message>
        <source>The file %1 does not exist.</source>
        <translation>Le fichier %1 n&apos;existe pas.</translation>
    </message>
    <message>
        <source>The image %1 is too small or too large: each side must be %2 – %3 px.</source>
        <translation>L&apos;image %1 est trop petite ou trop grande : chaque côté doit mesurer %2 – %3 px.</translation>
    </message>
    <message>
        <source>The file %1 is not an image this program reads (PNG, JPEG, EXR, TIFF).</source>
        <translation>Le fichier %1 n&apos;est pas une image que ce programme lit (PNG, JPEG, EXR, TIFF).</translation>
    </message>
    <message>
        <source>Exemplar image</source>
        <translation>Image d&apos;exemple</translation>
    </message>
    <message>
        <source>The bundled procedural exemplar</source>
        <translation>L&apos;exemple procédural fourni</translation>
    </message>
    <message>
        <source>Use your own image (PNG, JPEG, EXR, TIFF; %1 – %2 px a side): a crop of a real hysteroscopic view</source>
        <translation>Utiliser votre propre image (PNG, JPEG, EXR, TIFF ; %1 – %2 px de côté) : un extrait d&apos;une vue hystéroscopique réelle</translation>
    </message>
    <message>
        <source>Cervical canal</source>
        <translation>Canal cervical</translation>
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
        <translation>Exploration</translation>
    </message>
    <message>
        <source>Diagnosis</source>
        <translation>Diagnostic</translation>
    </message>
    <message>
        <source>Polypectomy</source>
        <translation>Polypectomie</translation>
    </message>
    <message>
        <source>Myomectomy</source>
        <translation>Myomectomie</translation>
    </message>
    <message>
        <source>&amp;Metrics</source>
        <translation>&amp;Mesures</translation>
    </message>
    <message>
        <source>&amp;Over Time</source>
        <translation>&amp;Au fil du temps</translation>
    </message>
    <message>
        <source>&amp;Visualized Surface</source>
        <translation>&amp;Surface visualisée</translation>
    </message>
    <message>
        <source>%1 trial, %2</source>
        <translation>Essai %1, %2</translation>
    </message>
    <message>
        <source>Scene %1, seed %2, %3° optic, %4 mm scope; device %5; physics %6.</source>
        <translation>Scène %1, graine %2, optique %3°, hystéroscope de %4 mm ; appareil %5 ; physique %6.</translation>
    </message>
    <message>
        <source>Started %1 (UTC).</source>
        <translation>Commencé %1 (UTC).</translation>
    </message>
    <message>
        <source>Report: %1</source>
        <translation>Rapport : %1</translation>
    </message>
    <message>
        <source>Open the trial&apos;s scene package for review (File &gt; Review Scene Package) to see its organ beside the report.</source>
        <translation>Ouvrez le paquet de scène de l&apos;essai pour examen (Fichier &gt; Examiner un paquet de scène) pour voir son organe à côté du rapport.</translation>
    </message>
    <message>
        <source>This trial ran on the scene under review.</source>
        <translation>Cet essai s&apos;est déroulé sur la scène examinée.</translation>
    </message>
    <message>
        <source>This trial ran on another scene than the one under review (%1, not %2).</source>
        <translation>Cet essai s&apos;est déroulé sur une autre scène que celle examinée (%1, pas %2).</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>temps (s)</translation>
    </message>
    <message>
        <source>Cavity surface, unrolled about the canal&apos;s axis</source>
        <translation>Surface de la cavité, déroulée autour de l&apos;axe du canal</translation>
    </message>
    <message>
        <source>seen</source>
        <translation>vu</translation>
    </message>
    <message>
        <source>not seen</source>
        <translation>non vu</translation>
    </message>
    <message>
        <source>around the axis (degrees; 0 anterior, +90 the patient&apos;s left)</source>
        <translation>autour de l&apos;axe (degrés ; 0 antérieur, +90 à gauche de la patiente)</translation>
    </message>
    <message>
        <source>from the internal os (mm)</source>
        <translation>depuis l&apos;orifice interne (mm)</translation>
    </message>
    <message>
        <source>&amp;Replay in the Simulator...</source>
        <translation>&amp;Rejouer dans le simulateur...</translation>
    </message>
    <message>
        <source>Play the recorded trial again in the simulator, on its scene package.</source>
        <translation>Rejouer l&apos;essai enregistré dans le simulateur, sur son paquet de scène.</translation>
    </message>
    <message>
        <source>No recorded trial (%1.trial) beside the report: the simulator writes one with the report when a trial ends.</source>
        <translation>Aucun essai enregistré (%1.trial) à côté du rapport : le simulateur l&apos;écrit avec le rapport à la fin d&apos;un essai.</translation>
    </message>
</context>
<context>
    <name>hs::widgets::VariantsView</name>
    <message>
        <source>How far every scope&apos;s tip is beyond its external os (mm)</source>
        <translation>Distance de la pointe de chaque hystéroscope au-delà de l&apos;orifice externe (mm)</translation>
    </message>
    <message>
        <source>&amp;Insertion</source>
        <translation>&amp;Insertion</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>&amp;Optic</source>
        <translation>&amp;Optique</translation>
    </message>
    <message>
        <source>&amp;Roll</source>
        <translation>&amp;Rotation</translation>
    </message>
</context>
<context>
    <name>hs::workstation::MainWindow</name>
    <message>
        <source>&amp;Open...</source>
        <translation>&amp;Ouvrir...</translation>
    </message>
    <message>
        <source>Open a surface or tetrahedral mesh</source>
        <translation>Ouvrir une surface ou un maillage tétraédrique</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <source>&amp;Clear Menu</source>
        <translation>&amp;Effacer le menu</translation>
    </message>
    <message>
        <source>&amp;Clip</source>
        <translation>&amp;Coupe</translation>
    </message>
    <message>
        <source>Cut the tetrahedral mesh open and show the tetrahedra on the cut</source>
        <translation>Ouvrir le maillage tétraédrique par une coupe et montrer les tétraèdres sur la coupe</translation>
    </message>
    <message>
        <source>&amp;Reset Camera</source>
        <translation>&amp;Réinitialiser la caméra</translation>
    </message>
    <message>
        <source>&amp;About Hysteroscene</source>
        <translation>À &amp;propos de Hysteroscene</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Fichiers &amp;récents</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Affichage</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>A&amp;ide</translation>
    </message>
    <message>
        <source>All meshes (%1)</source>
        <translation>Tous les maillages (%1)</translation>
    </message>
    <message>
        <source>Surface meshes (%1)</source>
        <translation>Maillages surfaciques (%1)</translation>
    </message>
    <message>
        <source>Tetrahedral meshes (%1)</source>
        <translation>Maillages tétraédriques (%1)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Open Mesh</source>
        <translation>Ouvrir un maillage</translation>
    </message>
    <message>
        <source>Opening %1...</source>
        <translation>Ouverture de %1...</translation>
    </message>
    <message>
        <source>The file %1 does not exist.</source>
        <translation>Le fichier %1 n&apos;existe pas.</translation>
    </message>
    <message>
        <source>The file %1 could not be read.</source>
        <translation>Le fichier %1 n&apos;a pas pu être lu.</translation>
    </message>
    <message>
        <source>The file %1 is in a format or version this program does not read.</source>
        <translation>Le fichier %1 est dans un format ou une version que ce programme ne lit pas.</translation>
    </message>
    <message>
        <source>The file %1 is larger than this program accepts.</source>
        <translation>Le fichier %1 dépasse la taille acceptée par ce programme.</translation>
    </message>
    <message>
        <source>The file %1 is not a valid mesh.</source>
        <translation>Le fichier %1 n&apos;est pas un maillage valide.</translation>
    </message>
    <message>
        <source>The file %1 could not be opened.</source>
        <translation>Le fichier %1 n&apos;a pas pu être ouvert.</translation>
    </message>
    <message>
        <source>Nothing picked</source>
        <translation>Aucun point sélectionné</translation>
    </message>
    <message>
        <source>Picked (%1, %2, %3) mm</source>
        <translation>Point sélectionné (%1 ; %2 ; %3) mm</translation>
    </message>
    <message>
        <source>No mesh</source>
        <translation>Aucun maillage</translation>
    </message>
    <message>
        <source>Vertices: %1   Tetrahedra: %2   Regions: %3</source>
        <translation>Sommets : %1   Tétraèdres : %2   Régions : %3</translation>
    </message>
    <message>
        <source>Shown: %1</source>
        <translation>Affichés : %1</translation>
    </message>
    <message>
        <source>Vertices: %1   Triangles: %2   Regions: %3</source>
        <translation>Sommets : %1   Triangles : %2   Régions : %3</translation>
    </message>
    <message>
        <source>About Hysteroscene</source>
        <translation>À propos de Hysteroscene</translation>
    </message>
    <message>
        <source>&amp;New Case</source>
        <translation>&amp;Nouveau cas</translation>
    </message>
    <message>
        <source>Start a new case from the default patient</source>
        <translation>Commencer un nouveau cas à partir de la patiente par défaut</translation>
    </message>
    <message>
        <source>Open &amp;Case...</source>
        <translation>Ouvrir un &amp;cas...</translation>
    </message>
    <message>
        <source>Open a case file (case.json)</source>
        <translation>Ouvrir un fichier de cas (case.json)</translation>
    </message>
    <message>
        <source>&amp;Save Case</source>
        <translation>&amp;Enregistrer le cas</translation>
    </message>
    <message>
        <source>Save Case &amp;As...</source>
        <translation>Enregistrer le cas &amp;sous...</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Annuler</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Rétablir</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>É&amp;dition</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Modifications non enregistrées</translation>
    </message>
    <message>
        <source>The case %1 has unsaved changes. Save them?</source>
        <translation>Le cas %1 a des modifications non enregistrées. Les enregistrer ?</translation>
    </message>
    <message>
        <source>The case file does not exist.</source>
        <translation>Le fichier de cas n&apos;existe pas.</translation>
    </message>
    <message>
        <source>The case file could not be read or written.</source>
        <translation>Le fichier de cas n&apos;a pas pu être lu ou écrit.</translation>
    </message>
    <message>
        <source>The case file is of a version this program does not read.</source>
        <translation>Le fichier de cas est d&apos;une version que ce programme ne lit pas.</translation>
    </message>
    <message>
        <source>The case file is larger than this program accepts.</source>
        <translation>Le fichier de cas est plus grand que ce que ce programme accepte.</translation>
    </message>
    <message>
        <source>The case is not valid: a value is outside its allowed range (see the details).</source>
        <translation>Le cas n&apos;est pas valide : une valeur est hors de sa plage autorisée (voir les détails).</translation>
    </message>
    <message>
        <source>The case could not be opened or saved.</source>
        <translation>Le cas n&apos;a pas pu être ouvert ou enregistré.</translation>
    </message>
    <message>
        <source>Open Case</source>
        <translation>Ouvrir un cas</translation>
    </message>
    <message>
        <source>Cases (*.json)</source>
        <translation>Cas (*.json)</translation>
    </message>
    <message>
        <source>Save Case</source>
        <translation>Enregistrer le cas</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>L&apos;enregistrement automatique a échoué : %1</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Sans titre</translation>
    </message>
    <message>
        <source>Recover Unsaved Changes</source>
        <translation>Récupérer les modifications non enregistrées</translation>
    </message>
    <message>
        <source>The last session ended with unsaved changes to the case %1. Recover them?</source>
        <translation>La dernière session s&apos;est terminée avec des modifications non enregistrées du cas %1. Les récupérer ?</translation>
    </message>
    <message>
        <source>Recen&amp;t Cases</source>
        <translation>Cas récen&amp;ts</translation>
    </message>
    <message>
        <source>Review Scene Package</source>
        <translation>Évaluer un paquet de scène</translation>
    </message>
    <message>
        <source>The scene package cannot be read: a file is missing, changed or breaks its format (see the details).</source>
        <translation>Le paquet de scène ne peut pas être lu : un fichier manque, a été modifié ou ne respecte pas son format (voir les détails).</translation>
    </message>
    <message>
        <source>Open an exported scene package read-only and rate how real it looks</source>
        <translation>Ouvrir un paquet de scène exporté en lecture seule et noter son réalisme</translation>
    </message>
    <message>
        <source>Close Re&amp;view</source>
        <translation>&amp;Fermer l&apos;évaluation</translation>
    </message>
    <message>
        <source>&amp;Panels</source>
        <translation>&amp;Panneaux</translation>
    </message>
    <message>
        <source>Patient</source>
        <translation>Patiente</translation>
    </message>
    <message>
        <source>Pathologies</source>
        <translation>Pathologies</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Matériaux</translation>
    </message>
    <message>
        <source>Mesh</source>
        <translation>Maillage</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Export</translation>
    </message>
    <message>
        <source>Texture</source>
        <translation>Texture</translation>
    </message>
    <message>
        <source>Review</source>
        <translation>Évaluation</translation>
    </message>
    <message>
        <source>Hysteroscopic View</source>
        <translation>Vue hystéroscopique</translation>
    </message>
    <message>
        <source>Exemplar Image</source>
        <translation>Image d&apos;exemple</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.exr *.tif *.tiff)</source>
        <translation>Images (*.png *.jpg *.jpeg *.exr *.tif *.tiff)</translation>
    </message>
    <message>
        <source>Export Scene Package</source>
        <translation>Exporter le paquet de scène</translation>
    </message>
    <message>
        <source>Reading the scene package</source>
        <translation>Lecture du paquet de scène</translation>
    </message>
    <message>
        <source>Unsaved Ratings</source>
        <translation>Notes non enregistrées</translation>
    </message>
    <message>
        <source>The review of %1 has unsaved ratings. Save them?</source>
        <translation>L&apos;évaluation de %1 a des notes non enregistrées. Les enregistrer ?</translation>
    </message>
    <message>
        <source>Organ</source>
        <translation>Organe</translation>
    </message>
    <message>
        <source>Grown pathologies</source>
        <translation>Pathologies après croissance</translation>
    </message>
    <message>
        <source>Merged body</source>
        <translation>Corps fusionné</translation>
    </message>
    <message>
        <source>Tetrahedral mesh</source>
        <translation>Maillage tétraédrique</translation>
    </message>
    <message>
        <source>Textured surface</source>
        <translation>Surface texturée</translation>
    </message>
    <message>
        <source>The case&apos;s %1, as the pipeline made it</source>
        <translation>%1 du cas, résultat du pipeline</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Hysteroscene %1&lt;/h3&gt;&lt;p&gt;A scenario authoring workstation for hysteroscopy training simulators.&lt;/p&gt;&lt;p&gt;Licensed under the GNU General Public License, version 3 or later.&lt;/p&gt;&lt;p&gt;&lt;small&gt;Built with %2.&lt;/small&gt;&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Hysteroscene %1&lt;/h3&gt;&lt;p&gt;Un poste de création de scénarios pour les simulateurs de formation à l&apos;hystéroscopie.&lt;/p&gt;&lt;p&gt;Distribué sous la licence publique générale GNU (GPL), version 3 ou ultérieure.&lt;/p&gt;&lt;p&gt;&lt;small&gt;Compilé avec %2.&lt;/small&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Revie&amp;w Scene Package...</source>
        <translation>É&amp;valuer un paquet de scène...</translation>
    </message>
    <message>
        <source>The folder holds no scene package (no manifest.json).</source>
        <translation>Le dossier ne contient aucun paquet de scène (pas de manifest.json).</translation>
    </message>
    <message>
        <source>Compare &amp;Variants...</source>
        <translation>Comparer les &amp;variantes...</translation>
    </message>
    <message>
        <source>Show the variants of a case side by side, as the scope sees them</source>
        <translation>Afficher côte à côte les variantes d&apos;un cas, telles que l&apos;hystéroscope les voit</translation>
    </message>
    <message>
        <source>Compare Variants</source>
        <translation>Comparer les variantes</translation>
    </message>
    <message>
        <source>Reading the variants</source>
        <translation>Lecture des variantes</translation>
    </message>
    <message>
        <source>Variants - %1</source>
        <translation>Variantes - %1</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Annuler : %1</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Rétablir : %1</translation>
    </message>
    <message>
        <source>&amp;Stages</source>
        <translation>É&amp;tapes</translation>
    </message>
    <message>
        <source>&amp;Place on the Wall</source>
        <translation>&amp;Placer sur la paroi</translation>
    </message>
    <message>
        <source>&amp;Grow</source>
        <translation>&amp;Faire croître</translation>
    </message>
    <message>
        <source>&amp;Mesh</source>
        <translation>&amp;Mailler</translation>
    </message>
    <message>
        <source>&amp;Texture</source>
        <translation>&amp;Texturer</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exporter</translation>
    </message>
    <message>
        <source>Cancel Placing</source>
        <translation>Annuler le placement</translation>
    </message>
    <message>
        <source>&amp;Orientation Marker</source>
        <translation>Repère d&apos;&amp;orientation</translation>
    </message>
    <message>
        <source>Show the patient&apos;s directions in the corner of the 3-D view</source>
        <translation>Afficher les directions de la patiente dans le coin de la vue 3D</translation>
    </message>
    <message>
        <source>&amp;Anterior</source>
        <translation>&amp;Antérieur</translation>
    </message>
    <message>
        <source>Look at the organ from in front of the patient</source>
        <translation>Regarder l&apos;organe de devant la patiente</translation>
    </message>
    <message>
        <source>&amp;Posterior</source>
        <translation>&amp;Postérieur</translation>
    </message>
    <message>
        <source>Look at the organ from behind the patient</source>
        <translation>Regarder l&apos;organe de derrière la patiente</translation>
    </message>
    <message>
        <source>&amp;Left</source>
        <translation>&amp;Gauche</translation>
    </message>
    <message>
        <source>Look at the organ from the patient&apos;s left</source>
        <translation>Regarder l&apos;organe depuis la gauche de la patiente</translation>
    </message>
    <message>
        <source>&amp;Right</source>
        <translation>&amp;Droite</translation>
    </message>
    <message>
        <source>Look at the organ from the patient&apos;s right</source>
        <translation>Regarder l&apos;organe depuis la droite de la patiente</translation>
    </message>
    <message>
        <source>&amp;Fundal</source>
        <translation>&amp;Fundique</translation>
    </message>
    <message>
        <source>Look down the uterine axis from above the fundus</source>
        <translation>Regarder le long de l&apos;axe utérin depuis le dessus du fond</translation>
    </message>
    <message>
        <source>From the External &amp;Os</source>
        <translation>Depuis l&apos;&amp;orifice externe</translation>
    </message>
    <message>
        <source>Look up the cervical canal from the external os, as the scope enters</source>
        <translation>Regarder le long du canal cervical depuis l&apos;orifice externe, comme l&apos;hystéroscope entre</translation>
    </message>
    <message>
        <source>Look &amp;From</source>
        <translation>&amp;Vue depuis</translation>
    </message>
    <message>
        <source>Views</source>
        <translation>Vues</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Scène</translation>
    </message>
    <message>
        <source>Out of date: the case has changed since this scene was made.</source>
        <translation>Périmé : le cas a changé depuis la création de cette scène.</translation>
    </message>
    <message>
        <source>on %1</source>
        <translation>sur %1</translation>
    </message>
    <message>
        <source>Out of date (%1): the case has changed since this view was made. It is remade when its stage runs again.</source>
        <translation>Périmé (%1) : le cas a changé depuis la création de cette vue. Elle sera refaite à la prochaine exécution de son étape.</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Ouvrir</translation>
    </message>
    <message>
        <source>A scene package is being reviewed, read-only: close the review (File &gt; Close Review) before opening %1.</source>
        <translation>Un paquet de scène est en cours d’évaluation, en lecture seule : fermez l’évaluation (Fichier &gt; Fermer l’évaluation) avant d’ouvrir %1.</translation>
    </message>
    <message>
        <source>The folder %1 holds no scene package (no manifest.json).</source>
        <translation>Le dossier %1 ne contient aucun paquet de scène (pas de manifest.json).</translation>
    </message>
    <message>
        <source>%1 is not a file this program opens: it opens cases (.json), scene packages (a folder with a manifest.json) and meshes (%2).</source>
        <translation>%1 n’est pas un fichier que ce programme ouvre : il ouvre des cas (.json), des paquets de scène (un dossier avec un manifest.json) et des maillages (%2).</translation>
    </message>
    <message>
        <source>Package Changed on Disk</source>
        <translation>Paquet modifié sur le disque</translation>
    </message>
    <message>
        <source>The scene package %1 has changed on disk since it was opened for review. Reload it? The ratings stay with the version you opened.</source>
        <translation>Le paquet de scène %1 a changé sur le disque depuis son ouverture pour évaluation. Le recharger ? Les évaluations restent attachées à la version ouverte.</translation>
    </message>
    <message>
        <source>The package has changed on disk since it was opened: what is shown, and rated, is the version opened.</source>
        <translation>Le paquet a changé sur le disque depuis son ouverture : ce qui est affiché et évalué est la version ouverte.</translation>
    </message>
    <message>
        <source>The case %1 has changed on disk, and you have unsaved changes. Reload it from disk? Your changes are lost.</source>
        <translation>Le cas %1 a changé sur le disque et vous avez des modifications non enregistrées. Le recharger depuis le disque ? Vos modifications seront perdues.</translation>
    </message>
    <message>
        <source>The case %1 has changed on disk. Reload it?</source>
        <translation>Le cas %1 a changé sur le disque. Le recharger ?</translation>
    </message>
    <message>
        <source>Case Changed on Disk</source>
        <translation>Cas modifié sur le disque</translation>
    </message>
    <message>
        <source>The case on disk differs from the one open; Save writes this one over it.</source>
        <translation>Le cas sur le disque diffère de celui ouvert ; Enregistrer écrit celui-ci par-dessus.</translation>
    </message>
    <message>
        <source>The case file %1 is gone from disk; Save writes it again.</source>
        <translation>Le fichier du cas %1 a disparu du disque ; Enregistrer le réécrit.</translation>
    </message>
    <message>
        <source>Review Trial Report</source>
        <translation>Examiner un rapport d&apos;essai</translation>
    </message>
    <message>
        <source>The trial report cannot be read: it is missing or breaks its format (see the details).</source>
        <translation>Le rapport d&apos;essai ne peut pas être lu : il est absent ou enfreint son format (voir les détails).</translation>
    </message>
    <message>
        <source>Review Trial Re&amp;port...</source>
        <translation>Examiner un ra&amp;pport d&apos;essai...</translation>
    </message>
    <message>
        <source>Show a simulator trial&apos;s metrics and plots from its report</source>
        <translation>Afficher les mesures et les courbes d&apos;un essai du simulateur à partir de son rapport</translation>
    </message>
    <message>
        <source>Trial reports (*.json);;All files (*)</source>
        <translation>Rapports d&apos;essai (*.json);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Reading the trial report</source>
        <translation>Lecture du rapport d&apos;essai</translation>
    </message>
    <message>
        <source>Trial Report - %1</source>
        <translation>Rapport d&apos;essai - %1</translation>
    </message>
    <message>
        <source>Replay</source>
        <translation>Relecture</translation>
    </message>
    <message>
        <source>The simulator is not installed beside the workstation.</source>
        <translation>Le simulateur n&apos;est pas installé à côté de la station de travail.</translation>
    </message>
    <message>
        <source>No executable %1.</source>
        <translation>Aucun exécutable %1.</translation>
    </message>
    <message>
        <source>The Scene Package the Trial Ran On</source>
        <translation>Le paquet de scène de l&apos;essai</translation>
    </message>
    <message>
        <source>The simulator did not start.</source>
        <translation>Le simulateur n&apos;a pas démarré.</translation>
    </message>
    <message>
        <source>Replaying %1 in the simulator.</source>
        <translation>Relecture de %1 dans le simulateur.</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Scenario authoring workstation for hysteroscopy training</source>
        <translation>Poste de création de scénarios pour la formation à l&apos;hystéroscopie</translation>
    </message>
    <message>
        <source>file</source>
        <translation>fichier</translation>
    </message>
    <message>
        <source>User-interface language (de, fr, it, en); default: HS_LANG, else the system locale.</source>
        <translation>Langue de l&apos;interface (de, fr, it, en) ; par défaut : HS_LANG, sinon la langue du système.</translation>
    </message>
    <message>
        <source>language</source>
        <translation>langue</translation>
    </message>
    <message>
        <source>Save the window to an image after loading, then quit.</source>
        <translation>Enregistrer la fenêtre dans une image après le chargement, puis quitter.</translation>
    </message>
    <message>
        <source>image</source>
        <translation>image</translation>
    </message>
    <message>
        <source>Open a tetrahedral mesh cut open.</source>
        <translation>Ouvrir un maillage tétraédrique coupé.</translation>
    </message>
    <message>
        <source>A case file (.json) to author, a scene package (a folder) or a simulator&apos;s trial report (.json) to review, or a surface or tetrahedral mesh to open.</source>
        <translation>Un fichier de cas (.json) à éditer, un paquet de scène (un dossier) ou un rapport d&apos;essai du simulateur (.json) à examiner, ou une surface ou un maillage tétraédrique à ouvrir.</translation>
    </message>
</context>
</TS>
