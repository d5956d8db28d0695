<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr">
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
        <source>&lt;h3&gt;Hysteroscene %1&lt;/h3&gt;&lt;p&gt;A scenario authoring workstation for hysteroscopy training simulators.&lt;/p&gt;&lt;p&gt;Licensed under the GNU General Public License, version 3 or later.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Hysteroscene %1&lt;/h3&gt;&lt;p&gt;Un poste de création de scénarios pour les simulateurs de formation à l&apos;hystéroscopie.&lt;/p&gt;&lt;p&gt;Distribué sous la licence publique générale GNU (GPL), version 3 ou ultérieure.&lt;/p&gt;</translation>
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
        <source>A surface or tetrahedral mesh to open.</source>
        <translation>Une surface ou un maillage tétraédrique à ouvrir.</translation>
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
</context>
</TS>
