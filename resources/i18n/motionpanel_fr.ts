<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr" sourcelanguage="en">
<context>
    <name>AboutDialog</name>
    <message>
        <location filename="../../widgets/about_dialog.py" line="+105"/>
        <source>About Motion Panel</source>
        <translation>À propos de Motion Panel</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Motion Panel</source>
        <translation>Motion Panel</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Version %1</source>
        <translation>Version %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown</source>
        <translation>inconnue</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A desktop control panel for serial stepper-motor positioning stages.</source>
        <translation>Panneau de commande de bureau pour platines de positionnement à moteurs pas à pas pilotées par liaison série.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>see LICENSE</source>
        <translation>voir LICENSE</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Licence: %1</source>
        <translation>Licence&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Components</source>
        <translation>Composants</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>not installed</source>
        <translation>non installé</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1:</source>
        <translation>%1&#xa0;:</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&amp;Copy details</source>
        <translation>&amp;Copier les détails</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Copy the versions, e.g. for a bug report</source>
        <translation>Copier les versions, par ex. pour un rapport de bogue</translation>
    </message>
</context>
<context>
    <name>ArcEntry</name>
    <message>
        <location filename="../../widgets/arc_entry.py" line="+274"/>
        <source>X of the arc&apos;s centre, in mm from home</source>
        <translation>X du centre de l&apos;arc, en mm depuis l&apos;origine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y of the arc&apos;s centre, in mm from home</source>
        <translation>Y du centre de l&apos;arc, en mm depuis l&apos;origine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Radius of the arc, in mm (more than 0)</source>
        <translation>Rayon de l&apos;arc, en mm (supérieur à 0)</translation>
    </message>
    <message>
        <location line="-127"/>
        <source>Angle of the start point, 0 to 360°, counter-clockwise from +X seen from above</source>
        <translation>Angle du point de départ, de 0 à 360°, dans le sens antihoraire depuis +X, vu de dessus</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Angle of the end point, 0 to 360°, counter-clockwise from +X seen from above;
the same as the start angle: a full circle</source>
        <translation>Angle du point d&apos;arrivée, de 0 à 360°, dans le sens antihoraire depuis +X, vu de dessus&#xa0;;
identique à l&apos;angle de départ&#xa0;: un cercle complet</translation>
    </message>
    <message>
        <location line="+120"/>
        <source>Z at the end of the arc, in mm; Z moves evenly from the current Z along the arc
(a helix when it differs)</source>
        <translation>Z à la fin de l&apos;arc, en mm&#xa0;; Z varie uniformément depuis le Z actuel le long de l&apos;arc
(une hélice s&apos;il diffère)</translation>
    </message>
    <message>
        <location line="-96"/>
        <source>Centre X:</source>
        <translation>Centre X&#xa0;:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Centre Y:</source>
        <translation>Centre Y&#xa0;:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Radius:</source>
        <translation>Rayon&#xa0;:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start:</source>
        <translation>Départ&#xa0;:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>End:</source>
        <translation>Arrivée&#xa0;:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Final Z:</source>
        <translation>Z final&#xa0;:</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>CW</source>
        <translation>Horaire</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Clockwise seen from above: the angle decreases</source>
        <translation>Sens horaire vu de dessus&#xa0;: l&apos;angle diminue</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CCW</source>
        <translation>Antihoraire</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Counter-clockwise seen from above: the angle increases</source>
        <translation>Sens antihoraire vu de dessus&#xa0;: l&apos;angle augmente</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Preview</source>
        <translation>Aperçu</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Draw the arc, dashed, in the position views</source>
        <translation>Tracer l&apos;arc en pointillés dans les vues de position</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Run arc</source>
        <translation>Exécuter l&apos;arc</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+189"/>
        <source>Move along the arc, from its start point to its end point</source>
        <translation>Se déplacer le long de l&apos;arc, de son point de départ à son point d&apos;arrivée</translation>
    </message>
    <message>
        <location line="-181"/>
        <source>Why the arc cannot run</source>
        <translation>Pourquoi l&apos;arc ne peut pas être exécuté</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>X of the arc&apos;s centre, in inches from home</source>
        <translation>X du centre de l&apos;arc, en pouces depuis l&apos;origine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y of the arc&apos;s centre, in inches from home</source>
        <translation>Y du centre de l&apos;arc, en pouces depuis l&apos;origine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Radius of the arc, in inches (more than 0)</source>
        <translation>Rayon de l&apos;arc, en pouces (supérieur à 0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Z at the end of the arc, in inches; Z moves evenly from the current Z along the arc
(a helix when it differs)</source>
        <translation>Z à la fin de l&apos;arc, en pouces&#xa0;; Z varie uniformément depuis le Z actuel le long de l&apos;arc
(une hélice s&apos;il diffère)</translation>
    </message>
    <message>
        <location line="+148"/>
        <source>The radius must be more than 0 in.</source>
        <translation>Le rayon doit être supérieur à 0 in.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The radius must be more than 0 mm.</source>
        <translation>Le rayon doit être supérieur à 0 mm.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 %2 to %3 in (travel %4 to %5 in)</source>
        <translation>%1 de %2 à %3 in (course de %4 à %5 in)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 %2 in (travel %3 to %4 in)</source>
        <translation>%1 %2 in (course de %3 à %4 in)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 %2 to %3 mm (travel %4 to %5 mm)</source>
        <translation>%1 de %2 à %3 mm (course de %4 à %5 mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 %2 mm (travel %3 to %4 mm)</source>
        <translation>%1 %2 mm (course de %3 à %4 mm)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>The arc leaves the travel limits: %1.</source>
        <translation>L&apos;arc sort des limites de course&#xa0;: %1.</translation>
    </message>
</context>
<context>
    <name>BridgeSession</name>
    <message>
        <location filename="../../app/window/device/bridge_session.py" line="+93"/>
        <source>the bridge failed: %1</source>
        <translation>la passerelle a échoué&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>the bridge stopped</source>
        <translation>la passerelle s&apos;est arrêtée</translation>
    </message>
</context>
<context>
    <name>CompactReadout</name>
    <message>
        <location filename="../../widgets/compact_readout.py" line="+34"/>
        <source>Stage position from the device&apos;s home</source>
        <translation>Position de la platine depuis l&apos;origine de l&apos;appareil</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2)</source>
        <comment>the position&apos;s tip, then its status</comment>
        <translation>%1 (%2)</translation>
    </message>
</context>
<context>
    <name>ConnectionBar</name>
    <message>
        <location filename="../../widgets/connection_bar.py" line="+32"/>
        <source>Disconnected</source>
        <translation>Déconnecté</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connecting…</source>
        <translation>Connexion…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connected</source>
        <translation>Connecté</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Error</source>
        <translation>Erreur</translation>
    </message>
    <message>
        <location line="+93"/>
        <source>/dev/ttyUSB0, COM3 or a URL</source>
        <translation>/dev/ttyUSB0, COM3 ou une URL</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Serial port, or any pyserial URL (e.g. sim://coxiris, socket://host:port, loop://)</source>
        <translation>Port série, ou toute URL pyserial (par ex. sim://coxiris, socket://host:port, loop://)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Look for serial ports again</source>
        <translation>Rechercher à nouveau les ports série</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The language the device speaks</source>
        <translation>Le langage que parle l&apos;appareil</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Variant:</source>
        <translation>Variante&#xa0;:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The wire variant of this protocol (packet format and rate)</source>
        <translation>La variante de ce protocole sur la ligne (format des paquets et débit)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Baud rate in bit/s (type any rate the device uses)</source>
        <translation>Débit en bauds, en bit/s (saisir tout débit utilisé par l&apos;appareil)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Bridge</source>
        <translation>Passerelle</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Bridge (snoop) mode: open the device&apos;s port and offer another program a pseudo-terminal; every byte is forwarded both ways unchanged and shown decoded here (motion controls are off while bridging)</source>
        <translation>Mode passerelle (espion)&#xa0;: ouvrir le port de l&apos;appareil et proposer un pseudo-terminal à un autre programme&#xa0;; chaque octet est transmis tel quel dans les deux sens et affiché ici décodé (les commandes de mouvement sont désactivées en mode passerelle)</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+6"/>
        <location line="+225"/>
        <source>Connect</source>
        <translation>Connecter</translation>
    </message>
    <message>
        <location line="-225"/>
        <location line="+224"/>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <location line="-224"/>
        <location line="+224"/>
        <source>Disconnect</source>
        <translation>Déconnecter</translation>
    </message>
    <message>
        <location line="-216"/>
        <source>Lines:</source>
        <translation>Lignes&#xa0;:</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&amp;Port:</source>
        <translation>&amp;Port&#xa0;:</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation type="vanished">Port&#xa0;:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Protocol:</source>
        <translation>Protocole&#xa0;:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Baud:</source>
        <translation>Bauds&#xa0;:</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>No description for this port</source>
        <translation>Aucune description pour ce port</translation>
    </message>
    <message>
        <location line="+111"/>
        <source>● %1: %2</source>
        <translation>● %1&#xa0;: %2</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Open the port and talk to the device</source>
        <translation>Ouvrir le port et dialoguer avec l&apos;appareil</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Close the connection</source>
        <translation>Fermer la connexion</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>choose or type a port</source>
        <translation>choisir ou saisir un port</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>choose a protocol</source>
        <translation>choisir un protocole</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the baud rate must be a positive whole number</source>
        <translation>le débit en bauds doit être un nombre entier positif</translation>
    </message>
</context>
<context>
    <name>ControlLinesBar</name>
    <message>
        <location filename="../../widgets/control_lines_bar.py" line="+47"/>
        <source>DTR</source>
        <translation>DTR</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RTS</source>
        <translation>RTS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CTS</source>
        <translation>CTS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DSR</source>
        <translation>DSR</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CD</source>
        <translation>CD</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RI</source>
        <translation>RI</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Data Terminal Ready</source>
        <translation>Terminal de données prêt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Request To Send</source>
        <translation>Demande pour émettre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear To Send</source>
        <translation>Prêt à émettre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data Set Ready</source>
        <translation>Poste de données prêt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Carrier Detect</source>
        <translation>Détection de porteuse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ring Indicator</source>
        <translation>Indicateur d&apos;appel</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Break</source>
        <translation>Break</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Send a break: hold the transmit line low for %1 ms (the device sees a framing error; some boards take it as a reset or attention signal)</source>
        <translation>Envoyer un break&#xa0;: maintenir la ligne d&apos;émission à l&apos;état bas pendant %1 ms (l&apos;appareil voit une erreur de trame&#xa0;; certaines cartes le prennent pour une réinitialisation ou un signal d&apos;attention)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>The serial port&apos;s control lines</source>
        <translation>Les lignes de contrôle du port série</translation>
    </message>
    <message>
        <location line="+49"/>
        <location line="+16"/>
        <source>%1 (%2): not connected</source>
        <translation>%1 (%2)&#xa0;: non connecté</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>%1 (%2): this port cannot set %1</source>
        <translation>%1 (%2)&#xa0;: ce port ne peut pas piloter %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (%2), driven by this computer: tick to assert it, untick to release it</source>
        <translation>%1 (%2), piloté par cet ordinateur&#xa0;: cocher pour l&apos;activer, décocher pour le relâcher</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>this port cannot report %1</source>
        <translation>ce port ne peut pas indiquer l&apos;état de %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2), driven by the device: on</source>
        <translation>%1 (%2), piloté par l&apos;appareil&#xa0;: actif</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2), driven by the device: off</source>
        <translation>%1 (%2), piloté par l&apos;appareil&#xa0;: inactif</translation>
    </message>
</context>
<context>
    <name>CoordinateEntry</name>
    <message>
        <location filename="../../widgets/coordinate_entry.py" line="+34"/>
        <source>Make the current position the new home (0, 0, 0)?
All coordinates will be measured from here from now on.</source>
        <translation>Faire de la position actuelle la nouvelle origine (0, 0, 0)&#xa0;?
Toutes les coordonnées seront désormais mesurées à partir d&apos;ici.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Motion Panel</source>
        <translation>Motion Panel</translation>
    </message>
    <message>
        <source>%1:</source>
        <comment>an axis field&apos;s label</comment>
        <translation type="vanished">%1&#xa0;:</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Absolute</source>
        <translation>Absolu</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>Go to the typed coordinates (mm from home)</source>
        <translation>Aller aux coordonnées saisies (mm depuis l&apos;origine)</translation>
    </message>
    <message>
        <location line="-71"/>
        <source>Relative</source>
        <translation>Relatif</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>Move by the typed distances (mm) from where the stage is</source>
        <translation>Se déplacer des distances saisies (mm) depuis la position actuelle de la platine</translation>
    </message>
    <message>
        <location line="-63"/>
        <source>Machine</source>
        <translation>Machine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Work</source>
        <translation>Pièce</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>Which frame the typed coordinates are in: Machine (mm from the device&apos;s home) or Work (mm from the work zero); the device is always sent machine coordinates</source>
        <translation>Repère des coordonnées saisies&#xa0;: Machine (mm depuis l&apos;origine de l&apos;appareil) ou Pièce (mm depuis le zéro pièce)&#xa0;; l&apos;appareil reçoit toujours des coordonnées machine</translation>
    </message>
    <message>
        <location line="-58"/>
        <source>Go</source>
        <translation>Aller</translation>
    </message>
    <message>
        <location line="-26"/>
        <source>&amp;%1:</source>
        <comment>an axis field&apos;s label; Alt+axis</comment>
        <translation>&amp;%1&#xa0;:</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Start the move (Enter in a field)</source>
        <translation>Lancer le mouvement (Entrée dans un champ)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Use current</source>
        <translation>Position actuelle</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fill the fields with the current position</source>
        <translation>Remplir les champs avec la position actuelle</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Home</source>
        <translation>Origine</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Run the homing sequence</source>
        <translation>Lancer la prise d&apos;origine</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Set Home</source>
        <translation>Définir l&apos;origine</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Make the current position the origin (asks first)</source>
        <translation>Faire de la position actuelle l&apos;origine (avec confirmation)</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+177"/>
        <source>Stop</source>
        <translation>Arrêt</translation>
    </message>
    <message>
        <location line="-177"/>
        <source>Stop the stage now</source>
        <translation>Arrêter la platine immédiatement</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the stage now (Esc)</source>
        <translation>Arrêter la platine immédiatement (Échap)</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Go to the typed coordinates (inches from home)</source>
        <translation>Aller aux coordonnées saisies (pouces depuis l&apos;origine)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Move by the typed distances (inches) from where the stage is</source>
        <translation>Se déplacer des distances saisies (pouces) depuis la position actuelle de la platine</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Which frame the typed coordinates are in: Machine (inches from the device&apos;s home) or Work (inches from the work zero); the device is always sent machine coordinates, in mm</source>
        <translation>Repère des coordonnées saisies&#xa0;: Machine (pouces depuis l&apos;origine de l&apos;appareil) ou Pièce (pouces depuis le zéro pièce)&#xa0;; l&apos;appareil reçoit toujours des coordonnées machine, en mm</translation>
    </message>
    <message>
        <location line="+147"/>
        <source>Drop queued</source>
        <translation>Vider la file</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1 distance to move, %2 to %3 in (%4)</source>
        <translation>Distance à parcourir sur %1, de %2 à %3 in (%4)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 target coordinate, %2 to %3 in (%4)</source>
        <translation>Coordonnée cible %1, de %2 à %3 in (%4)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 target coordinate in the work frame, %2 to %3 in (%4)</source>
        <translation>Coordonnée cible %1 dans le repère pièce, de %2 à %3 in (%4)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 distance to move, %2 to %3 mm (%4)</source>
        <translation>Distance à parcourir sur %1, de %2 à %3 mm (%4)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 target coordinate, %2 to %3 mm (%4)</source>
        <translation>Coordonnée cible %1, de %2 à %3 mm (%4)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 target coordinate in the work frame, %2 to %3 mm (%4)</source>
        <translation>Coordonnée cible %1 dans le repère pièce, de %2 à %3 mm (%4)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>travel limits</source>
        <translation>limites de course</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no travel limits set</source>
        <translation>aucune limite de course définie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(this device has no such axis)</source>
        <translation>(cet appareil n&apos;a pas cet axe)</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1; nothing sent</source>
        <translation>%1&#xa0;; rien n&apos;a été envoyé</translation>
    </message>
</context>
<context>
    <name>DerivedValues</name>
    <message>
        <location filename="../../widgets/parameter_table.py" line="+501"/>
        <source>Derived values</source>
        <translation>Valeurs dérivées</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Computed from the values in the table, not read from the device</source>
        <translation>Calculées à partir des valeurs du tableau, non lues sur l&apos;appareil</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>a parameter</source>
        <translation>un paramètre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>needs a value for %1</source>
        <translation>nécessite une valeur pour %1</translation>
    </message>
</context>
<context>
    <name>DeviceDocks</name>
    <message>
        <location filename="../../app/window/docks/device_docks.py" line="+93"/>
        <source>Not now: %1</source>
        <translation>Indisponible pour le moment&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>%1 on %2</source>
        <translation>%1 sur %2</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>%1 to %2 mm on every axis (16-bit ticks)</source>
        <translation>de %1 à %2 mm sur chaque axe (impulsions sur 16 bits)</translation>
    </message>
    <message>
        <source>program %1: %2 points, nothing sent yet</source>
        <translation type="vanished">programme %1&#xa0;: %2 points, rien n&apos;a encore été envoyé</translation>
    </message>
    <message>
        <source>program saved to %1 (%2 points)</source>
        <translation type="vanished">programme enregistré dans %1 (%2 points)</translation>
    </message>
    <message>
        <source>the program stopped: %1</source>
        <translation type="vanished">le programme s&apos;est arrêté&#xa0;: %1</translation>
    </message>
    <message>
        <source>program %1 done: %2/%3 executed, %4 frames, %5 retransmission(s), %6 s</source>
        <translation type="vanished">programme %1 terminé&#xa0;: %2/%3 exécutées, %4 trames, %5 retransmission(s), %6 s</translation>
    </message>
    <message>
        <source>program %1 stopped, the device&apos;s queue flushed: %2/%3 executed, %4 frames, %5 retransmission(s), %6 s</source>
        <translation type="vanished">programme %1 arrêté, file de l&apos;appareil vidée&#xa0;: %2/%3 exécutées, %4 trames, %5 retransmission(s), %6 s</translation>
    </message>
</context>
<context>
    <name>DockLayout</name>
    <message>
        <location filename="../../app/window/layout/dock_layout.py" line="+16"/>
        <source>Stepper setup</source>
        <translation>Configuration du moteur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frame setup</source>
        <translation>Configuration du cadre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Program</source>
        <translation>Programme</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Arc</source>
        <translation>Arc</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dwell</source>
        <translation>Temporisation</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Travel limits</source>
        <translation>Limites de course</translation>
    </message>
</context>
<context>
    <name>DwellEntry</name>
    <message>
        <location filename="../../widgets/dwell_entry.py" line="+28"/>
        <source>Dwell:</source>
        <translation>Temporisation&#xa0;:</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>How long the device waits, 0 to %1 ms; press Enter or Dwell to send</source>
        <translation>Durée d&apos;attente de l&apos;appareil, de 0 à %1 ms&#xa0;; appuyer sur Entrée ou Temporiser pour envoyer</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Dwell</source>
        <translation>Temporiser</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Make the device wait this long before its next command</source>
        <translation>Faire attendre l&apos;appareil pendant cette durée avant sa commande suivante</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1; nothing sent</source>
        <translation>%1&#xa0;; rien n&apos;a été envoyé</translation>
    </message>
</context>
<context>
    <name>FirmataPanel</name>
    <message>
        <location filename="../../widgets/firmata_panel.py" line="+31"/>
        <source>version unknown</source>
        <translation>version inconnue</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Full steps per revolution of the motor, 1 to %1 (e.g. 200)</source>
        <translation>Pas entiers par tour du moteur, de 1 à %1 (par ex. 200)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 pins</source>
        <translation>%1 broches</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>2 pins: a driver with step and direction inputs; 4 pins: the motor&apos;s four wires</source>
        <translation>2 broches&#xa0;: un driver avec entrées pas et direction&#xa0;; 4 broches&#xa0;: les quatre fils du moteur</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>pin </source>
        <translation>broche </translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Motor steps per mm of travel (more than 0): converts mm and mm/s to steps</source>
        <translation>Pas moteur par mm de course (supérieur à 0)&#xa0;: convertit les mm et mm/s en pas</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The speed in mm/s and the motor speed it means, in revolutions per minute</source>
        <translation>La vitesse en mm/s et la vitesse moteur correspondante, en tours par minute</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Configure</source>
        <translation>Configurer</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Set up the stepper on the board with these settings</source>
        <translation>Configurer le moteur pas à pas sur la carte avec ces réglages</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Library version</source>
        <translation>Version de la bibliothèque</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ask the board for its stepper library&apos;s version</source>
        <translation>Demander à la carte la version de sa bibliothèque pas à pas</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The stepper library version the board reported</source>
        <translation>La version de la bibliothèque pas à pas indiquée par la carte</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Steps/rev:</source>
        <translation>Pas/tour&#xa0;:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Steps per mm:</source>
        <translation>Pas par mm&#xa0;:</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Pins:</source>
        <translation>Broches&#xa0;:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The board&apos;s pin numbers (0 to %1) wired to the motor</source>
        <translation>Les numéros des broches de la carte (0 à %1) reliées au moteur</translation>
    </message>
    <message>
        <location line="+111"/>
        <source>step</source>
        <translation>pas</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>direction</source>
        <translation>direction</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>motor wire</source>
        <translation>fil moteur</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pin %1 (%2), 0 to %3</source>
        <translation>Broche %1 (%2), de 0 à %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not used</source>
        <translation>non utilisée</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+2"/>
        <source>speed: %1 mm/s = %2 rpm</source>
        <translation>vitesse&#xa0;: %1 mm/s = %2 rpm</translation>
    </message>
</context>
<context>
    <name>Jobs</name>
    <message>
        <location filename="../../app/window/device/jobs.py" line="+25"/>
        <source>move to (%1, %2, %3) mm</source>
        <translation>déplacement vers (%1, %2, %3) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>jog by (%1, %2, %3) %4</source>
        <translation>déplacement relatif de (%1, %2, %3) %4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>relative move by (%1, %2, %3) %4</source>
        <translation>mouvement relatif de (%1, %2, %3) %4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>go home</source>
        <translation>retour à l&apos;origine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set home here</source>
        <translation>définition de l&apos;origine ici</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set speed %1 mm/s</source>
        <translation>réglage de la vitesse à %1 mm/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set %1 = %2 %3</source>
        <translation>réglage de %1 = %2 %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>arc around (%1, %2) mm, radius %3 mm, from %4° to %5° CCW</source>
        <translation>déplacement en arc autour de (%1, %2) mm, rayon %3 mm, de %4° à %5°, sens antihoraire</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>arc around (%1, %2) mm, radius %3 mm, from %4° to %5° CW</source>
        <translation>déplacement en arc autour de (%1, %2) mm, rayon %3 mm, de %4° à %5°, sens horaire</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dwell %1 ms</source>
        <translation>temporisation de %1 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set %1</source>
        <translation>réglage de %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>configure the stepper: %1 steps/rev on pins %2</source>
        <translation>configuration du moteur pas à pas&#xa0;: %1 pas/tour sur les broches %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ask the stepper library version</source>
        <translation>demande de la version de la bibliothèque pas à pas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>run %1 (%2 points)</source>
        <translation>lancement de %1 (%2 points)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>run %1 (%2 lines)</source>
        <translation>lancement de %1 (%2 lignes)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>run %1 (%2 entities)</source>
        <translation>lancement de %1 (%2 entités)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>run %1 (%2 elements)</source>
        <translation>lancement de %1 (%2 éléments)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>send &quot;%1&quot;</source>
        <translation>transmission de «&#xa0;%1&#xa0;»</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>refresh position and speed</source>
        <translation>relecture de la position et de la vitesse</translation>
    </message>
</context>
<context>
    <name>JogPanel</name>
    <message>
        <location filename="../../widgets/jog_panel.py" line="+35"/>
        <source>Keys: ←/→ X, ↑/↓ Y, PgUp/PgDn Z, Shift ×10</source>
        <translation>Touches&#xa0;: ←/→ X, ↑/↓ Y, Page préc/Page suiv Z, Maj ×10</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Move the stage by one step; hold a button or key to keep stepping.
%1 (see the hint below for where the keys work).</source>
        <translation>Déplacer la platine d&apos;un pas&#xa0;; maintenir un bouton ou une touche enfoncé pour continuer.
%1 (voir l&apos;indication ci-dessous pour savoir où les touches fonctionnent).</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Step:</source>
        <translation>Pas&#xa0;:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Distance of one jog</source>
        <translation>Distance d&apos;un déplacement</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+14"/>
        <source>Jog by %1 per press</source>
        <translation>Déplacer de %1 par appui</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>%1 in</source>
        <translation>%1 in</translation>
    </message>
    <message>
        <location line="+131"/>
        <source>Any step size (%1 to %2 in)</source>
        <translation>Pas quelconque (de %1 à %2 in)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Any step size (0.001 to 1000 mm)</source>
        <translation>Pas quelconque (de 0,001 à 1000 mm)</translation>
    </message>
    <message>
        <location line="+174"/>
        <source>%1; no jog</source>
        <translation>%1&#xa0;; aucun déplacement</translation>
    </message>
    <message>
        <location line="-256"/>
        <source>keys active</source>
        <translation>touches actives</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>keys off: %1</source>
        <translation>touches inactives&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The jog keys work while this window is active and no menu, list, dialog or popup
is open, except when the focus is in a field that uses the arrow keys itself
(text and number fields, drop-down lists, the speed slider, the console).
Click the views or this panel to give the keys back to jogging.
Hold a key to keep stepping; Shift for a step ten times bigger.</source>
        <translation>Les touches de déplacement fonctionnent tant que cette fenêtre est active et qu&apos;aucun menu, liste, dialogue
ou fenêtre contextuelle n&apos;est ouvert, sauf si le focus est dans un champ qui utilise lui-même les flèches
(champs de texte et numériques, listes déroulantes, curseur de vitesse, console).
Cliquer sur les vues ou sur ce panneau pour rendre les touches au déplacement.
Maintenir une touche pour continuer&#xa0;; Maj pour un pas dix fois plus grand.</translation>
    </message>
    <message>
        <location line="+103"/>
        <source>Jog %1 by %2 in (Shift: %3 in)</source>
        <translation>Déplacer %1 de %2 in (Maj&#xa0;: %3 in)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Jog %1 by %2 mm (Shift: %3 mm)</source>
        <translation>Déplacer %1 de %2 mm (Maj&#xa0;: %3 mm)</translation>
    </message>
</context>
<context>
    <name>KeyboardJog</name>
    <message>
        <location filename="../../app/window/keyboard_jog.py" line="+38"/>
        <source>a text field</source>
        <translation>un champ de texte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a number field</source>
        <translation>un champ numérique</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a drop-down list</source>
        <translation>une liste déroulante</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a slider</source>
        <translation>un curseur</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a list or text view</source>
        <translation>une liste ou une zone de texte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a choice</source>
        <translation>un choix</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the menu bar</source>
        <translation>la barre de menus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a menu</source>
        <translation>un menu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tabs</source>
        <translation>une barre d&apos;onglets</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>not connected</source>
        <translation>non connecté</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>a menu or list is open</source>
        <translation>un menu ou une liste est ouvert</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a dialog is open</source>
        <translation>une boîte de dialogue est ouverte</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>another window is active</source>
        <translation>une autre fenêtre est active</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the focus is in %1</source>
        <translation>le focus est dans %1</translation>
    </message>
</context>
<context>
    <name>LogViewer</name>
    <message>
        <location filename="../../app/window/console/log_viewer.py" line="+48"/>
        <source>(undecoded)</source>
        <translation>(non décodé)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Open traffic log</source>
        <translation>Ouvrir un journal de trafic</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Logs (*.log *.txt);;All files (*)</source>
        <translation>Journaux (*.log *.txt);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Traffic log</source>
        <translation>Journal de trafic</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Decode with this protocol (chosen from the log&apos;s connection note when it has one)</source>
        <translation>Décoder avec ce protocole (choisi d&apos;après la note de connexion du journal, s&apos;il en a une)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Open…</source>
        <translation>Ouvrir…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open a Motion Panel log or a pyserial spy:// capture</source>
        <translation>Ouvrir un journal Motion Panel ou une capture pyserial spy://</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no log open</source>
        <translation>aucun journal ouvert</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Close</source>
        <translation>Fermer</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Close this log&apos;s window (Ctrl+W, Esc)</source>
        <translation>Fermer la fenêtre de ce journal (Ctrl+W, Échap)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Protocol:</source>
        <translation>Protocole&#xa0;:</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>reading %1…</source>
        <translation>lecture de %1…</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>%1 — traffic log</source>
        <translation>%1 — journal de trafic</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (%2): %3 lines, decoded as %4</source>
        <translation>%1 (%2)&#xa0;: %3 lignes, décodées en %4</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>, recognised from its traffic (the log names no protocol)</source>
        <translation>, reconnu d&apos;après son trafic (le journal n&apos;indique aucun protocole)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>; a simulator&apos;s record: TX and RX shown as the host saw them</source>
        <translation>; enregistrement d&apos;un simulateur&#xa0;: TX et RX affichés tels que l&apos;hôte les a vus</translation>
    </message>
</context>
<context>
    <name>MacroDock</name>
    <message>
        <location filename="../../app/window/docks/macro_dock.py" line="+30"/>
        <source>Motion Panel macros (*.json);;All files (*)</source>
        <translation>Macros Motion Panel (*.json);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Macros</source>
        <translation>Macros</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Steps (one per line, each waits for the device): home · set-home · position · move X Y [Z] (mm) · jog DX DY [DZ] (mm) · speed V (mm/s) · raw TEXT (sent as typed, its reply awaited) · wait S (s, the panel pauses) · check · id · limits; and where the device has them: dwell MS (ms) · arc CX CY R START END --cw|--ccw · step RPM STEPS · status · stop · version.</source>
        <comment>the command words (home, move, --cw …) are typed as they are: keep them in English</comment>
        <translation>Étapes (une par ligne, chacune attend l&apos;appareil)&#xa0;: home · set-home · position · move X Y [Z] (mm) · jog DX DY [DZ] (mm) · speed V (mm/s) · raw TEXTE (envoyé tel que saisi, sa réponse attendue) · wait S (s, le panneau fait une pause) · check · id · limits&#xa0;; et si l&apos;appareil les possède&#xa0;: dwell MS (ms) · arc CX CY R DÉBUT FIN --cw|--ccw · step RPM PAS · status · stop · version.</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Macros (%1)</source>
        <translation>Macros (%1)</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1; nothing sent</source>
        <translation>%1&#xa0;; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>macro %1: step %2/%3: %4</source>
        <translation>macro %1&#xa0;: étape %2/%3&#xa0;: %4</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>choose a protocol first</source>
        <translation>choisir d&apos;abord un protocole</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a macro named %1 exists already</source>
        <translation>une macro nommée %1 existe déjà</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>macro %1 kept (%2 steps)</source>
        <translation>macro %1 enregistrée (%2 étapes)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>macro %1 deleted</source>
        <translation>macro %1 supprimée</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 macros; at most %2</source>
        <translation>%1 macros&#xa0;; %2 au maximum</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>macros not imported: %1</source>
        <translation>macros non importées&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>; %1 for other protocols left out</source>
        <translation>; %1 pour d&apos;autres protocoles ignorée(s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>imported %1 macro(s) from %2%3</source>
        <translation>%1 macro(s) importée(s) depuis %2%3</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>macros not exported: cannot write %1: %2</source>
        <translation>macros non exportées&#xa0;: impossible d&apos;écrire %1&#xa0;: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>exported %1 macro(s) to %2</source>
        <translation>%1 macro(s) exportée(s) vers %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Import macros</source>
        <translation>Importer des macros</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Export macros</source>
        <translation>Exporter des macros</translation>
    </message>
</context>
<context>
    <name>MacroEditor</name>
    <message>
        <location filename="../../widgets/macro_editor.py" line="+51"/>
        <source>Edit macro</source>
        <translation>Modifier la macro</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>New macro</source>
        <translation>Nouvelle macro</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The button&apos;s label: 1 to 40 characters</source>
        <translation>Le libellé du bouton&#xa0;: 1 à 40 caractères</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>One step per line, as motionctl takes it: distances in mm, speeds in mm/s, waits in s. Each step waits for the device&apos;s reply before the next.</source>
        <translation>Une étape par ligne, comme motionctl les accepte&#xa0;: distances en mm, vitesses en mm/s, attentes en s. Chaque étape attend la réponse de l&apos;appareil avant la suivante.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Delete</source>
        <translation>Supprimer</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Remove this macro</source>
        <translation>Supprimer cette macro</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Name:</source>
        <translation>&amp;Nom&#xa0;:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Steps:</source>
        <translation>É&amp;tapes&#xa0;:</translation>
    </message>
</context>
<context>
    <name>MacroPanel</name>
    <message>
        <location filename="../../widgets/macro_panel.py" line="+37"/>
        <source>No macros yet: New… writes one, Import… reads a file.</source>
        <translation>Aucune macro pour l&apos;instant&#xa0;: Nouvelle… en crée une, Importer… lit un fichier.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>New…</source>
        <translation>Nouvelle…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Write a new macro</source>
        <translation>Écrire une nouvelle macro</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Edit</source>
        <translation>Modifier</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Change or delete a macro</source>
        <translation>Modifier ou supprimer une macro</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Import…</source>
        <translation>Importer…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add the macros of a file (JSON; data only, checked before any is kept)</source>
        <translation>Ajouter les macros d&apos;un fichier (JSON&#xa0;; données uniquement, vérifiées avant tout enregistrement)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export…</source>
        <translation>Exporter…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Write this protocol&apos;s macros to a file</source>
        <translation>Écrire les macros de ce protocole dans un fichier</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Run %1:
%2</source>
        <translation>Exécuter %1&#xa0;:
%2</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Macros off: %1</source>
        <translation>Macros désactivées&#xa0;: %1</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <location filename="../../app/window/layout/fit_controls.py" line="+18"/>
        <source>%1 has no stop command: this drops the commands not yet sent; a move already under way on the device finishes (Esc)</source>
        <translation>Aucune commande d&apos;arrêt sur %1&#xa0;: ceci vide les commandes pas encore envoyées&#xa0;; un mouvement déjà en cours sur l&apos;appareil se termine (Échap)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Stop the stage now: halts the move under way and drops what is queued (Esc)</source>
        <translation>Arrêter la platine immédiatement&#xa0;: interrompt le mouvement en cours et vide la file d&apos;attente (Échap)</translation>
    </message>
    <message>
        <location filename="../../app/window/device/connection.py" line="+57"/>
        <source>simulated %1 device</source>
        <translation>appareil %1 simulé</translation>
    </message>
    <message>
        <location filename="../../app/window/main_window.py" line="+101"/>
        <source>Motion Panel</source>
        <translation>Motion Panel</translation>
    </message>
    <message>
        <location filename="../../app/window/device/worker_link.py" line="+113"/>
        <source>no session log: %1</source>
        <translation>pas de journal de session&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>session log: %1</source>
        <translation>journal de session&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>no session log from now on</source>
        <translation>plus de journal de session à partir de maintenant</translation>
    </message>
    <message>
        <location filename="../../app/window/main_window.py" line="+130"/>
        <source>Connection</source>
        <translation>Connexion</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jog</source>
        <translation>Déplacement</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Go to</source>
        <translation>Aller à</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed</source>
        <translation>Vitesse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Console</source>
        <translation>Console</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Parameters</source>
        <translation>Paramètres</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Traffic timeline</source>
        <translation>Chronologie du trafic</translation>
    </message>
    <message>
        <location filename="../../app/window/menus.py" line="+26"/>
        <source>&amp;File</source>
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export traffic log…</source>
        <translation>&amp;Exporter le journal de trafic…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save every byte sent and received, with timestamps, to a text file</source>
        <translation>Enregistrer chaque octet envoyé et reçu, horodaté, dans un fichier texte</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Open log…</source>
        <translation>&amp;Ouvrir un journal…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Browse a traffic log (ours or a pyserial spy:// capture) decoded</source>
        <translation>Parcourir un journal de trafic décodé (un des nôtres ou une capture pyserial spy://)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Open the session &amp;log folder</source>
        <translation>Ouvrir le &amp;dossier des journaux de session</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Every byte of every session is kept there, one file a session</source>
        <translation>Chaque octet de chaque session y est conservé, un fichier par session</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Motion</source>
        <translation>&amp;Mouvement</translation>
    </message>
    <message>
        <location filename="../../app/window/layout/fit_controls.py" line="+49"/>
        <location filename="../../app/window/menus.py" line="+1"/>
        <source>&amp;Stop</source>
        <translation>&amp;Arrêt</translation>
    </message>
    <message>
        <location filename="../../app/window/menus.py" line="+4"/>
        <source>&amp;Travel limits…</source>
        <translation>&amp;Limites de course…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The box the stage may move in, for this device</source>
        <translation>La zone où la platine peut se déplacer, pour cet appareil</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;View</source>
        <translation>&amp;Affichage</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Reset views</source>
        <translation>&amp;Réinitialiser les vues</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Clear trail</source>
        <translation>&amp;Effacer la trace</translation>
    </message>
    <message>
        <location filename="../../app/window/device/connection.py" line="+76"/>
        <source>%1 names its protocol: connecting as %2</source>
        <translation>%1 indique son protocole&#xa0;: connexion en tant que %2</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>connecting to %1 (%2, %3 baud)</source>
        <translation>connexion à %1 (%2, %3 bauds)</translation>
    </message>
    <message>
        <location line="+88"/>
        <source>bridge refused: %1</source>
        <translation>passerelle refusée&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>bridge: %1</source>
        <translation>passerelle&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>bridging %1 to %2</source>
        <translation>passerelle de %1 vers %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bridge: another program can open %1; every byte goes to %2</source>
        <translation>passerelle&#xa0;: un autre programme peut ouvrir %1&#xa0;; chaque octet est transmis à %2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>bridge ended: %1</source>
        <translation>passerelle terminée&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>bridge closed</source>
        <translation>passerelle fermée</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>connection error: %1</source>
        <translation>erreur de connexion&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+9"/>
        <source>disconnected</source>
        <translation>déconnecté</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>disconnected from %1 on %2</source>
        <translation>déconnecté de %1 sur %2</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>connected to %1 on %2</source>
        <translation>connecté à %1 sur %2</translation>
    </message>
    <message>
        <location filename="../../app/window/device/machine_state.py" line="+38"/>
        <source>home set: the position is counted from here</source>
        <translation>origine définie&#xa0;: la position est comptée à partir d&apos;ici</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>an absolute point reached: the position is counted from here</source>
        <translation>point absolu atteint&#xa0;: la position est comptée à partir d&apos;ici</translation>
    </message>
    <message>
        <location line="+53"/>
        <location line="+116"/>
        <source>the position is unknown: this device cannot report it; home it or set home</source>
        <translation>la position est inconnue&#xa0;: cet appareil ne peut pas l&apos;indiquer&#xa0;; faire une prise d&apos;origine ou définir l&apos;origine</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>connected again to %1: the position was read again</source>
        <translation>reconnecté à %1&#xa0;: la position a été relue</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the device cannot be asked where it is: it goes on from (%1, %2, %3) mm, where it was left on this port (kept, not measured)</source>
        <translation>l&apos;appareil ne peut pas être interrogé sur sa position&#xa0;: il repart de (%1, %2, %3) mm, là où il a été laissé sur ce port (conservée, non mesurée)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>position unknown: the device cannot be asked; Home or Set Home to start counting</source>
        <translation>position inconnue&#xa0;: l&apos;appareil ne peut pas être interrogé&#xa0;; «&#xa0;Origine&#xa0;» ou «&#xa0;Définir l&apos;origine&#xa0;» pour commencer le décompte</translation>
    </message>
    <message>
        <location filename="../../app/window/layout/fit_controls.py" line="-41"/>
        <source>the device</source>
        <translation>l&apos;appareil</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Go to the home position (0, 0, 0)</source>
        <translation>Aller à la position d&apos;origine (0, 0, 0)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Make the current position the origin (asks first)</source>
        <translation>Faire de la position actuelle l&apos;origine (avec confirmation)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Restart the panel&apos;s count of the position here (asks first); %1 has no set-home command, so nothing is sent</source>
        <translation>Faire repartir d&apos;ici le décompte de position du panneau (avec confirmation)&#xa0;; %1 n&apos;a pas de commande pour définir l&apos;origine, rien n&apos;est donc envoyé</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>&amp;Drop queued commands</source>
        <translation>&amp;Vider la file d&apos;attente</translation>
    </message>
    <message>
        <location filename="../../app/window/device/connection.py" line="+58"/>
        <source>port %1 appeared</source>
        <translation>port %1 apparu</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>reconnecting to %1</source>
        <translation>reconnexion à %1</translation>
    </message>
    <message>
        <location line="-296"/>
        <source>port %1 disappeared</source>
        <translation>port %1 disparu</translation>
    </message>
    <message>
        <location line="+309"/>
        <source>%1 on %2</source>
        <translation>%1 sur %2</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>none</source>
        <translation>aucune</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>travel limits: %1</source>
        <translation>limites de course&#xa0;: %1</translation>
    </message>
    <message>
        <location filename="../../app/window/device/job_desk.py" line="+115"/>
        <source>not connected: %1 not sent</source>
        <translation>non connecté&#xa0;: %1 non envoyé</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 refused: the position is unknown, so the program&apos;s coordinates would not be where it goes; Home or Set Home first</source>
        <translation>%1 refusé : la position est inconnue, les coordonnées du programme ne seraient donc pas là où il va ; faites d&apos;abord Origine ou Définir l&apos;origine</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 refused: the position is unknown and this device moves only to absolute targets, so it would go elsewhere; Set Home, Home or Go to first</source>
        <translation>%1 refusé&#xa0;: la position est inconnue et cet appareil ne se déplace que vers des cibles absolues, il irait donc ailleurs&#xa0;; faites d&apos;abord Définir l&apos;origine, Origine ou Aller à</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 refused: %2 is under way; wait for its end or press Stop</source>
        <translation>%1 refusé&#xa0;: %2 est en cours&#xa0;; attendre sa fin ou appuyer sur Arrêt</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>motion controls are off until %1 ends (Stop ends it now)</source>
        <translation>les commandes de mouvement sont désactivées jusqu&apos;à la fin de %1 (Arrêt y met fin immédiatement)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1 is under way</source>
        <translation>%1 est en cours</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>jog refused: %1</source>
        <translation>déplacement refusé&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+92"/>
        <source>Send unchecked bytes?</source>
        <translation>Envoyer des octets non vérifiés&#xa0;?</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>These bytes cannot be read as a command (%1), so they cannot be checked against the travel limits (%2): they might move the stage outside them.

Send them anyway?</source>
        <translation>Ces octets ne peuvent pas être lus comme une commande (%1)&#xa0;: ils ne peuvent donc pas être vérifiés par rapport aux limites de course (%2) et pourraient amener la platine hors de celles-ci.

Les envoyer quand même&#xa0;?</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>not sent: the bytes could not be checked against the travel limits</source>
        <translation>non envoyés&#xa0;: les octets n&apos;ont pas pu être vérifiés par rapport aux limites de course</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>stopping the macro under way</source>
        <translation>arrêt de la macro en cours</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>stopping the move under way</source>
        <translation>arrêt du mouvement en cours</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>nothing queued; the move under way finishes</source>
        <translation>rien en file d&apos;attente&#xa0;; le mouvement en cours se termine</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>stopped: %1 command(s) not sent: %2</source>
        <translation>arrêté&#xa0;: %1 commande(s) non envoyée(s)&#xa0;: %2</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>%1: %2</source>
        <translation>%1&#xa0;: %2</translation>
    </message>
    <message>
        <location filename="../../app/window/device/machine_state.py" line="+65"/>
        <source>new home: the trail is shifted by (%1, %2, %3) mm</source>
        <translation>nouvelle origine&#xa0;: la trace est décalée de (%1, %2, %3) mm</translation>
    </message>
    <message>
        <location line="-147"/>
        <source>the device reported an error: %1</source>
        <translation>l&apos;appareil a signalé une erreur&#xa0;: %1</translation>
    </message>
    <message>
        <location filename="../../app/window/device/connection.py" line="-125"/>
        <location filename="../../app/window/device/machine_state.py" line="+5"/>
        <source>device: %1</source>
        <translation>appareil&#xa0;: %1</translation>
    </message>
    <message>
        <location filename="../../app/window/device/job_desk.py" line="-11"/>
        <source>%1 failed: %2</source>
        <translation>échec de %1&#xa0;: %2</translation>
    </message>
    <message>
        <location filename="../../app/window/device/machine_state.py" line="-118"/>
        <source>home confirmed: the position is counted from here</source>
        <translation>origine confirmée&#xa0;: la position est comptée à partir d&apos;ici</translation>
    </message>
    <message>
        <location line="+204"/>
        <source>position unknown: the device cannot be asked and its frames carry absolute targets, so a jog is refused; Set Home where the stage stands, Home, or Go to an absolute point first</source>
        <translation>position inconnue&#xa0;: l&apos;appareil ne peut pas être interrogé et ses trames portent des cibles absolues, un déplacement est donc refusé&#xa0;; d&apos;abord «&#xa0;Définir l&apos;origine&#xa0;» là où se trouve la platine, «&#xa0;Origine&#xa0;», ou «&#xa0;Aller à&#xa0;» vers un point absolu</translation>
    </message>
    <message>
        <location line="+206"/>
        <source>speed %1 mm/s reads back as %2 mm/s (the device rounds)</source>
        <translation>vitesse %1 mm/s relue comme %2 mm/s (l&apos;appareil arrondit)</translation>
    </message>
    <message>
        <location filename="../../app/window/layout/arrangements.py" line="+93"/>
        <source>&amp;Operate</source>
        <translation>&amp;Pilotage</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Set up</source>
        <translation>&amp;Configuration</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Traffic</source>
        <translation>&amp;Trafic</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Jog, go to and watch the stage: the views large</source>
        <translation>Déplacer la platine, l&apos;envoyer à une position et la surveiller&#xa0;: les vues en grand</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The device&apos;s parameters and setup panels, and macros</source>
        <translation>Les paramètres et panneaux de configuration de l&apos;appareil, et les macros</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The traffic console and its timeline, full width</source>
        <translation>La console de trafic et sa chronologie, en pleine largeur</translation>
    </message>
    <message>
        <location filename="../../app/window/layout/layouts.py" line="+112"/>
        <source>Reset &amp;layout</source>
        <translation>Réinitialiser la di&amp;sposition</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Put the docks of this layout back as they were at first</source>
        <translation>Remettre les panneaux de cette disposition comme au départ</translation>
    </message>
    <message>
        <location line="+274"/>
        <source>this device has parameters: %1 for Set up</source>
        <translation>cet appareil a des paramètres&#xa0;: %1 pour «&#xa0;Configuration&#xa0;»</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>this device has a setup panel: %1 for Set up</source>
        <translation>cet appareil a un panneau de configuration&#xa0;: %1 pour «&#xa0;Configuration&#xa0;»</translation>
    </message>
    <message>
        <location filename="../../app/window/device/program_pause.py" line="+22"/>
        <source>paused: nothing more is sent; the move under way finishes (this device has no feed hold)</source>
        <translation>en pause&#xa0;: plus rien n&apos;est envoyé&#xa0;; le mouvement en cours se termine (cet appareil n&apos;a pas de suspension d&apos;avance)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>resumed: sending the program again</source>
        <translation>repris&#xa0;: le programme est de nouveau envoyé</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>paused: nothing more is sent; the device still holds %1 move(s) and runs them (its protocol has no feed hold): it stands still in about %2 s; Stop flushes them now</source>
        <translation>en pause&#xa0;: plus rien n&apos;est envoyé&#xa0;; l&apos;appareil contient encore %1 mouvement(s) et les exécute (son protocole n&apos;a pas de suspension d&apos;avance)&#xa0;: il sera immobile dans %2 s environ&#xa0;; «&#xa0;Arrêt&#xa0;» les annule tout de suite</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>paused: the device has run what it held; the stage stands still</source>
        <translation>en pause&#xa0;: l&apos;appareil a exécuté ce qu&apos;il contenait&#xa0;; la platine est immobile</translation>
    </message>
</context>
<context>
    <name>NumberField</name>
    <message>
        <location filename="../../widgets/_number_field.py" line="+35"/>
        <source>a number is needed, %1 to %2%3</source>
        <translation>un nombre est requis, de %1 à %2%3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1%2 is not a whole number</source>
        <translation>%1%2 n&apos;est pas un nombre entier</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>“%1” is not a number (%2 to %3%4)</source>
        <translation>«&#xa0;%1&#xa0;» n&apos;est pas un nombre (de %2 à %3%4)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1%4 is outside %2 to %3%4</source>
        <translation>%1%4 est hors de la plage de %2 à %3%4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1%2 has more than %3 decimals</source>
        <translation>%1%2 a plus de %3 décimales</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2</source>
        <translation>%1&#xa0;: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1; cleared when the units changed to %2</source>
        <translation>%1&#xa0;; effacé lors du passage des unités en %2</translation>
    </message>
</context>
<context>
    <name>ParameterDock</name>
    <message>
        <location filename="../../app/window/docks/parameter_dock.py" line="+34"/>
        <source>the device now holds %1: the firmware forces it after every set</source>
        <translation>l&apos;appareil contient maintenant %1&#xa0;: le firmware l&apos;impose après chaque écriture</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>steps</source>
        <translation>pas</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>Parameters</source>
        <translation>Paramètres</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>Parameters (%1)</source>
        <translation>Paramètres (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 on %2</source>
        <translation>%1 sur %2</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>parameter writing cancelled: %1 not sent</source>
        <translation>écriture des paramètres annulée&#xa0;: %1 non envoyé(s)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>not sent</source>
        <translation>non envoyé</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>recomputed by the firmware at the last move</source>
        <translation>recalculé par le firmware lors du dernier mouvement</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the device did not answer</source>
        <translation>l&apos;appareil n&apos;a pas répondu</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>connect to a device with parameters first</source>
        <translation>se connecter d&apos;abord à un appareil doté de paramètres</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>loaded %1 values from %2; nothing sent (Write changed sends them)</source>
        <translation>%1 valeurs chargées depuis %2&#xa0;; rien n&apos;a été envoyé (le bouton «&#xa0;Écrire les modifications&#xa0;» les envoie)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>left out, computed by the firmware: %1</source>
        <translation>écarté(s), calculé(s) par le firmware&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>saved %1 values to %2</source>
        <translation>%1 valeurs enregistrées dans %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (firmware outputs are never saved)</source>
        <translation>%1 (les sorties du firmware ne sont jamais enregistrées)</translation>
    </message>
</context>
<context>
    <name>ParameterEditor</name>
    <message>
        <location filename="../../widgets/parameter_editor.py" line="+49"/>
        <source>Parameter profiles (*.toml);;All files (*)</source>
        <translation>Profils de paramètres (*.toml);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>The device cannot be read back: this compares with what this panel last wrote</source>
        <translation>L&apos;appareil ne peut pas être relu&#xa0;: la comparaison porte sur ce que ce panneau a écrit en dernier</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Packets written so far; each is confirmed before the next</source>
        <translation>Paquets écrits jusqu&apos;ici&#xa0;; chacun est confirmé avant le suivant</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Write selected</source>
        <translation>Écrire la sélection</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write the values of the selected rows</source>
        <translation>Écrire les valeurs des lignes sélectionnées</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Write all</source>
        <translation>Tout écrire</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write every value in the table, one packet each</source>
        <translation>Écrire toutes les valeurs du tableau, un paquet par valeur</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Write changed</source>
        <translation>Écrire les modifications</translation>
    </message>
    <message>
        <source>Write the values marked • (not yet written)</source>
        <translation type="vanished">Écrire les valeurs marquées • (pas encore écrites)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop writing after the packet under way</source>
        <translation>Arrêter l&apos;écriture après le paquet en cours</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Load profile…</source>
        <translation>Charger un profil…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fill the table from a file</source>
        <translation>Remplir le tableau depuis un fichier</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save profile…</source>
        <translation>Enregistrer le profil…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Save the values to a file</source>
        <translation>Enregistrer les valeurs dans un fichier</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Not loaded: %1</source>
        <translation>Non chargé&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+151"/>
        <source>nothing sent</source>
        <translation>rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write finished: %1</source>
        <translation>Écriture terminée&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 / %2 packets, about %3 left</source>
        <translation>%1 / %2 paquets, reste environ %3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no row selected</source>
        <translation>aucune ligne sélectionnée</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the table has no values</source>
        <translation>le tableau ne contient aucune valeur</translation>
    </message>
    <message>
        <source>nothing differs</source>
        <translation type="vanished">aucune différence</translation>
    </message>
    <message>
        <location line="-238"/>
        <source>Write the input values marked • (they differ from what the device holds); firmware outputs are not written by it</source>
        <translation>Écrire les valeurs d&apos;entrée marquées • (elles diffèrent de ce que contient l&apos;appareil)&#xa0;; les sorties du firmware ne sont pas écrites par ce bouton</translation>
    </message>
    <message>
        <location line="+247"/>
        <source>no input differs</source>
        <translation>aucune entrée ne diffère</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Nothing to write: %1</source>
        <translation>Rien à écrire&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Writing 1 value</source>
        <translation>Écriture d&apos;une valeur</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writing %1 values</source>
        <translation>Écriture de %1 valeurs</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no value, not written: %1</source>
        <translation>sans valeur, non écrit(s)&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>computed by the firmware, which may replace them: %1</source>
        <translation>calculé(s) par le firmware, qui peut les remplacer&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Warning: %1</source>
        <translation>Avertissement&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cancelling: the packet under way finishes, the rest are not sent</source>
        <translation>Annulation&#xa0;: le paquet en cours se termine, les suivants ne sont pas envoyés</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Save parameter profile</source>
        <translation>Enregistrer le profil de paramètres</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Load parameter profile</source>
        <translation>Charger un profil de paramètres</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>No parameters</source>
        <translation>Aucun paramètre</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No values yet: load a profile or type them into the Value column</source>
        <translation>Aucune valeur pour l&apos;instant&#xa0;: charger un profil ou les saisir dans la colonne Valeur</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>1 value differs from what was last written to this device (marked •)</source>
        <translation>1 valeur diffère de la dernière valeur écrite sur cet appareil (marquée •)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 values differ from what was last written to this device (marked •)</source>
        <translation>%1 valeurs diffèrent des dernières valeurs écrites sur cet appareil (marquées •)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Every value is what was last written to this device</source>
        <translation>Toutes les valeurs sont celles écrites en dernier sur cet appareil</translation>
    </message>
</context>
<context>
    <name>ParameterModel</name>
    <message>
        <location filename="../../widgets/parameter_table.py" line="-467"/>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Name</source>
        <translation>Nom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit</source>
        <translation>Unité</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Value</source>
        <translation>Valeur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Last written</source>
        <translation>Dernière écriture</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Kind</source>
        <translation>Type</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Description</source>
        <translation>Description</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Status</source>
        <translation>État</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The value to write, in the unit beside it (double-click, F2, Enter or type)</source>
        <translation>La valeur à écrire, dans l&apos;unité indiquée à côté (double-clic, F2, Entrée ou saisie directe)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>What this panel last wrote to the device (the device cannot be read back)</source>
        <translation>Ce que ce panneau a écrit en dernier sur l&apos;appareil (l&apos;appareil ne peut pas être relu)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>input: set by you; output: computed by the firmware</source>
        <translation>entrée&#xa0;: définie par vous&#xa0;; sortie&#xa0;: calculée par le firmware</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The outcome of the last write of this parameter</source>
        <translation>Le résultat de la dernière écriture de ce paramètre</translation>
    </message>
    <message>
        <location line="+92"/>
        <source>%1 (computed)</source>
        <translation>%1 (calculé)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 (power-on)</source>
        <translation>%1 (mise sous tension)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>output</source>
        <translation>sortie</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>input</source>
        <translation>entrée</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Input: set by you and written to the device</source>
        <translation>Entrée&#xa0;: définie par vous et écrite sur l&apos;appareil</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: never written to this device from this panel; it holds %2 from power-on</source>
        <translation>%1&#xa0;: jamais écrit sur cet appareil depuis ce panneau&#xa0;; il contient %2 depuis la mise sous tension</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: never written to this device from this panel</source>
        <translation>%1&#xa0;: jamais écrit sur cet appareil depuis ce panneau</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the device holds %2, computed by its firmware %3</source>
        <translation>%1&#xa0;: l&apos;appareil contient %2, calculé par son firmware %3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: last written %2</source>
        <translation>%1&#xa0;: dernière valeur écrite&#xa0;: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Allowed: %1</source>
        <translation>Valeurs autorisées&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Value: %1</source>
        <translation>Valeur&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>• Differs from what was last written to this device</source>
        <translation>• Diffère de la dernière valeur écrite sur cet appareil</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>%1: no such parameter</source>
        <translation>%1&#xa0;: paramètre inexistant</translation>
    </message>
</context>
<context>
    <name>ParameterTableView</name>
    <message>
        <location line="+185"/>
        <source>Double-click a value, or select a row and press Enter or type, to edit</source>
        <translation>Pour modifier&#xa0;: double-cliquer sur une valeur, ou sélectionner une ligne puis appuyer sur Entrée ou saisir</translation>
    </message>
</context>
<context>
    <name>ParameterValues</name>
    <message>
        <location filename="../../widgets/parameter_values.py" line="+40"/>
        <source>not written</source>
        <translation>non écrit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pending</source>
        <translation>en attente</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>confirmed</source>
        <translation>confirmé</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error</source>
        <translation>erreur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timed out</source>
        <translation>délai dépassé</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancelled</source>
        <translation>annulé</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>after the last set</source>
        <translation>après la dernière écriture</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>at the last move</source>
        <translation>lors du dernier mouvement</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Output: computed by the firmware. Writing it is allowed, but the firmware may replace what is written.</source>
        <translation>Sortie&#xa0;: calculée par le firmware. L&apos;écrire est permis, mais le firmware peut remplacer la valeur écrite.</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1 to %2, whole numbers</source>
        <translation>%1 à %2, nombres entiers</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 to %2 in steps of %3</source>
        <translation>%1 à %2 par pas de %3</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1: %2 refused (%3): %4</source>
        <translation>%1&#xa0;: %2 refusé (%3)&#xa0;: %4</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>empty</source>
        <translation>vide</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>use a point for decimals</source>
        <translation>utiliser un point comme séparateur décimal</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not a number</source>
        <translation>pas un nombre</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>not a finite number</source>
        <translation>pas un nombre fini</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>below the minimum</source>
        <translation>inférieur au minimum</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>above the maximum</source>
        <translation>supérieur au maximum</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not a multiple of %1</source>
        <translation>pas un multiple de %1</translation>
    </message>
</context>
<context>
    <name>PiFramePanel</name>
    <message>
        <location filename="../../widgets/piframe_panel.py" line="+17"/>
        <source>DTR on</source>
        <translation>DTR actif</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DTR off</source>
        <translation>DTR inactif</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DTR unknown</source>
        <translation>DTR inconnu</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Encoder ticks per mm of travel (more than 0): converts the frame&apos;s ticks to mm</source>
        <translation>Impulsions codeur par mm de course (supérieur à 0)&#xa0;: convertit les impulsions du cadre en mm</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The state of the serial DTR line, which powers the frame</source>
        <translation>L&apos;état de la ligne série DTR, qui alimente le cadre</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The range the frame can reach, from its travel and ticks/mm</source>
        <translation>La plage que le cadre peut atteindre, d&apos;après sa course et ses impulsions/mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unknown</source>
        <translation>inconnue</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Ticks per mm:</source>
        <translation>Impulsions par mm&#xa0;:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DTR:</source>
        <translation>DTR&#xa0;:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reachable:</source>
        <translation>Atteignable&#xa0;:</translation>
    </message>
</context>
<context>
    <name>PortWatcher</name>
    <message>
        <location filename="../../app/window/device/ports.py" line="+22"/>
        <source>serial port</source>
        <translation>port série</translation>
    </message>
</context>
<context>
    <name>PositionReadout</name>
    <message>
        <location filename="../../widgets/position_readout.py" line="+26"/>
        <source>commanded, not measured</source>
        <translation>commandée, non mesurée</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>commanded, move confirmed</source>
        <translation>commandée, mouvement confirmé</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This device does not report its position: the numbers are where it was told to go.</source>
        <translation>Cet appareil n&apos;indique pas sa position&#xa0;: les valeurs affichées sont celles de la consigne envoyée.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Where the device was told to go, and its reply said the move ended there; not read back (a device that can report its position is asked again when idle).</source>
        <translation>Position de consigne, et la réponse de l&apos;appareil indique que le mouvement s&apos;y est terminé&#xa0;; non relue (un appareil capable d&apos;indiquer sa position est réinterrogé au repos).</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>position unknown: the device cannot be asked; Home or Set Home to start counting</source>
        <translation>position inconnue&#xa0;: l&apos;appareil ne peut pas être interrogé&#xa0;; «&#xa0;Origine&#xa0;» ou «&#xa0;Définir l&apos;origine&#xa0;» pour commencer le décompte</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>position unknown: the link failed or the device restarted, and it cannot report where it is; home it or set home</source>
        <translation>position inconnue&#xa0;: la liaison a échoué ou l&apos;appareil a redémarré, et il ne peut pas indiquer où il se trouve&#xa0;; faire une prise d&apos;origine ou définir l&apos;origine</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>estimated from the speed: the device cannot be asked while it moves</source>
        <translation>estimée d&apos;après la vitesse&#xa0;: l&apos;appareil ne peut pas être interrogé pendant un mouvement</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>estimated when the link was lost, during a move: somewhere between its start and its target; not connected</source>
        <translation>estimée lors de la perte de la liaison, pendant un mouvement&#xa0;: quelque part entre son départ et sa cible&#xa0;; non connecté</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>bridging: no position seen in the bridged traffic yet (the panel asks nothing)</source>
        <translation>passerelle&#xa0;: aucune position vue pour l&apos;instant dans le trafic de la passerelle (le panneau n&apos;interroge rien)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>observed in the bridged traffic: the device reported this position to the other program</source>
        <translation>observée dans le trafic de la passerelle&#xa0;: l&apos;appareil a indiqué cette position à l&apos;autre programme</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>observed in the bridged traffic: the target of a move the other program sent, not confirmed by the device</source>
        <translation>observée dans le trafic de la passerelle&#xa0;: la cible d&apos;un mouvement envoyé par l&apos;autre programme, non confirmée par l&apos;appareil</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>last known position: not connected</source>
        <translation>dernière position connue&#xa0;: non connecté</translation>
    </message>
    <message>
        <source>Stage position in mm: from the device&apos;s home, and from the work zero</source>
        <translation type="vanished">Position de la platine en mm&#xa0;: depuis l&apos;origine de l&apos;appareil et depuis le zéro pièce</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>Machine</source>
        <translation>Machine</translation>
    </message>
    <message>
        <source>Millimetres from the device&apos;s home (its origin)</source>
        <translation type="vanished">Millimètres depuis l&apos;origine de l&apos;appareil (son point de référence)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Work</source>
        <translation>Pièce</translation>
    </message>
    <message>
        <source>Millimetres from the work zero the panel keeps (the device is not told)</source>
        <translation type="vanished">Millimètres depuis le zéro pièce conservé par le panneau (l&apos;appareil n&apos;en est pas informé)</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Distances from the device&apos;s home (its origin)</source>
        <translation>Distances depuis l&apos;origine de l&apos;appareil (son point de référence)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Distances from the work zero the panel keeps (the device is not told)</source>
        <translation>Distances depuis le zéro pièce conservé par le panneau (l&apos;appareil n&apos;en sait rien)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Zero %1</source>
        <translation>Zéro %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Make the current %1 the work zero (0 mm in the work frame); the device is not told, and its home stays where it is</source>
        <translation>Prendre la position %1 actuelle comme zéro pièce (0 mm dans le repère pièce)&#xa0;; l&apos;appareil n&apos;en est pas informé et son origine reste inchangée</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Zero all</source>
        <translation>Tout à zéro</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Make the current position the work zero</source>
        <translation>Prendre la position actuelle comme zéro pièce</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Clear zero</source>
        <translation>Effacer le zéro</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Put the work zero back at the device&apos;s home (work = machine)</source>
        <translation>Ramener le zéro pièce à l&apos;origine de l&apos;appareil (pièce = machine)</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>The stage is outside the travel limits set for this device: only moves that bring it closer to them are sent, until it is back inside</source>
        <translation>La platine est hors des limites de course définies pour cet appareil&#xa0;: seuls les mouvements qui l&apos;en rapprochent sont envoyés, jusqu&apos;à ce qu&apos;elle y soit revenue</translation>
    </message>
    <message>
        <location line="+121"/>
        <source>outside the travel limits: %1</source>
        <translation>hors des limites de course&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+101"/>
        <source>millimetres</source>
        <translation>millimètres</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>inches</source>
        <translation>pouces</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stage position in %1: from the device&apos;s home, and from the work zero</source>
        <translation>Position de la platine en %1&#xa0;: depuis l&apos;origine de l&apos;appareil, et depuis le zéro pièce</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>This device has no %1 axis</source>
        <translation>Cet appareil n&apos;a pas d&apos;axe %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Position unknown</source>
        <translation>Position inconnue</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 position in %2 from the device&apos;s home</source>
        <translation>Position %1 en %2 depuis l&apos;origine de l&apos;appareil</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 position in %2 from the work zero</source>
        <translation>Position %1 en %2 depuis le zéro pièce</translation>
    </message>
    <message>
        <source>%1 position in mm from the device&apos;s home</source>
        <translation type="vanished">Position %1 en mm depuis l&apos;origine de l&apos;appareil</translation>
    </message>
    <message>
        <source>%1 position in mm from the work zero</source>
        <translation type="vanished">Position %1 en mm depuis le zéro pièce</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>work zero: home</source>
        <translation>zéro pièce&#xa0;: origine</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>work zero at (%1) %2 (machine)</source>
        <translation>zéro pièce à (%1) %2 (machine)</translation>
    </message>
    <message>
        <source>work zero at %1 mm (machine)</source>
        <translation type="vanished">zéro pièce à %1 mm (machine)</translation>
    </message>
</context>
<context>
    <name>PositionView2D</name>
    <message>
        <location filename="../../widgets/view2d/xy_plot.py" line="+27"/>
        <source>Stage seen from above: trail, current position (dot; hollow when estimated), target (+), travel limits (dashed)</source>
        <translation>Platine vue de dessus&#xa0;: trace, position actuelle (point&#xa0;; creux si estimée), cible (+), limites de course (pointillés)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>XY (from above)</source>
        <translation>XY (vue de dessus)</translation>
    </message>
    <message>
        <location filename="../../widgets/position_view_2d.py" line="+150"/>
        <source>X (mm)</source>
        <translation>X (mm)</translation>
    </message>
    <message>
        <location line="-4"/>
        <location line="+4"/>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y (mm)</source>
        <translation>Y (mm)</translation>
    </message>
    <message>
        <location line="-4"/>
        <location line="+4"/>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <location filename="../../widgets/view2d/time_plot.py" line="+37"/>
        <source>X, Y and Z against time; dashed lines: target</source>
        <translation>X, Y et Z en fonction du temps&#xa0;; pointillés&#xa0;: cible</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Position against time</source>
        <translation>Position en fonction du temps</translation>
    </message>
    <message>
        <location filename="../../widgets/position_view_2d.py" line="-5"/>
        <source>X (in)</source>
        <translation>X (in)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y (in)</source>
        <translation>Y (in)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>time (s, 0 = latest sample)</source>
        <translation>temps (s, 0 = dernier échantillon)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>t (s)</source>
        <translation>t (s)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>position (in)</source>
        <translation>position (in)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>in</source>
        <translation>in</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position (mm)</source>
        <translation>position (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <location line="-68"/>
        <source>Clear trail</source>
        <translation>Effacer la trace</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Forget the path so far (the current position stays)</source>
        <translation>Oublier le chemin parcouru (la position actuelle reste)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reset view</source>
        <translation>Réinitialiser la vue</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Zoom both plots to fit the data again</source>
        <translation>Recadrer les deux graphiques sur les données</translation>
    </message>
</context>
<context>
    <name>PositionView3D</name>
    <message>
        <location filename="../../widgets/view3d/navigation.py" line="+19"/>
        <source>Top</source>
        <translation>Dessus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>View from above (X right, Y up)</source>
        <translation>Vue de dessus (X vers la droite, Y vers le haut)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Front</source>
        <translation>Face</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>View from the front (X right, Z up)</source>
        <translation>Vue de face (X vers la droite, Z vers le haut)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Side</source>
        <translation>Côté</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>View from the side (Y right, Z up)</source>
        <translation>Vue de côté (Y vers la droite, Z vers le haut)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Iso</source>
        <translation>Iso</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>View from above at an angle</source>
        <translation>Vue de dessus en biais</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Fit</source>
        <translation>Ajuster</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zoom to the trail, the target and the workspace</source>
        <translation>Cadrer la trace, la cible et l&apos;espace de travail</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Follow</source>
        <translation>Suivre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep the camera on the current position</source>
        <translation>Garder la caméra sur la position actuelle</translation>
    </message>
    <message>
        <location filename="../../widgets/view3d/notice.py" line="+15"/>
        <source>Needs OpenGL 2.1 or newer (e.g. Mesa) on a display; see the README.</source>
        <translation>Nécessite OpenGL 2.1 ou plus récent (par ex. Mesa) sur un affichage&#xa0;; voir le README.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>3D view unavailable: OpenGL could not be initialised.
(%1)
The 2D view shows the same positions.</source>
        <translation>Vue 3D indisponible&#xa0;: OpenGL n&apos;a pas pu être initialisé.
(%1)
La vue 2D montre les mêmes positions.</translation>
    </message>
    <message>
        <location filename="../../widgets/position_view_3d.py" line="+109"/>
        <source>Drag to rotate, wheel to zoom, middle-drag to pan</source>
        <translation>Glisser pour pivoter, molette pour zoomer, glisser avec le bouton du milieu pour déplacer la vue</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>grid %1 in</source>
        <translation>grille %1 in</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>grid %1 mm</source>
        <translation>grille %1 mm</translation>
    </message>
</context>
<context>
    <name>Preferences</name>
    <message>
        <location filename="../../app/window/preferences.py" line="+67"/>
        <source>Stop (Motion menu)</source>
        <translation>Arrêt (menu Mouvement)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the console&apos;s next match</source>
        <translation>l&apos;occurrence suivante dans la console</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>moving the focus</source>
        <translation>déplacer le focus</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>connecting and sending</source>
        <translation>se connecter et envoyer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pressing the focused button</source>
        <translation>appuyer sur le bouton actif</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>Poll while moving</source>
        <translation>Interrogation en mouvement</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Poll when idle</source>
        <translation>Interrogation au repos</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Console lines kept</source>
        <translation>Lignes de console conservées</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lines</source>
        <translation>lignes</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Session log</source>
        <translation>Journal de session</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Session log folder</source>
        <translation>Dossier du journal de session</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Units shown</source>
        <translation>Unités affichées</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Decimals shown</source>
        <translation>Décimales affichées</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>decimals</source>
        <translation>décimales</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Clamp moves to the limits</source>
        <translation>Borner les mouvements aux limites</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>smaller step</source>
        <translation>pas plus petit</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>larger step</source>
        <translation>pas plus grand</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Theme</source>
        <translation>Thème</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Language</source>
        <translation>Langue</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Jog key %1</source>
        <translation>Touche %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 to %2 %3</source>
        <translation>de %1 à %2 %3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: %2 lines is out of range: 0 (keep every line) or %3</source>
        <translation>%1&#xa0;: %2 lignes, hors plage&#xa0;: 0 (conserver toutes les lignes) ou %3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2 is out of range: -1 (as the device resolves) or %3</source>
        <translation>%1&#xa0;: %2 est hors plage&#xa0;: -1 (selon la résolution de l&apos;appareil) ou %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2 %3 is out of range (%4)</source>
        <translation>%1&#xa0;: %2 %3 est hors plage (%4)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>it must be an absolute path</source>
        <translation>ce doit être un chemin absolu</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>it does not exist</source>
        <translation>il n&apos;existe pas</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>it is not a folder</source>
        <translation>ce n&apos;est pas un dossier</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>it is not writable</source>
        <translation>il n&apos;est pas accessible en écriture</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>it must be a single key</source>
        <translation>ce doit être une seule touche</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>it is not a key the panel can use</source>
        <translation>ce n&apos;est pas une touche utilisable par le panneau</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no Shift, Ctrl, Alt or Meta: Shift makes the step ten times bigger</source>
        <translation>sans Maj, Ctrl, Alt ni Méta&#xa0;: Maj multiplie le pas par dix</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the window uses it for %1</source>
        <translation>la fenêtre l&apos;utilise pour %1</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1: choose a key</source>
        <translation>%1&#xa0;: choisir une touche</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: %2 cannot be used: %3</source>
        <translation>%1&#xa0;: %2 est inutilisable&#xa0;: %3</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: %2 is already %3</source>
        <translation>%1&#xa0;: %2 est déjà affectée à %3</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1: %2: %3</source>
        <translation>%1&#xa0;: %2&#xa0;: %3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: %2 is not one of %3</source>
        <translation>%1&#xa0;: %2 n&apos;est pas parmi %3</translation>
    </message>
</context>
<context>
    <name>ProgramDock</name>
    <message>
        <location filename="../../app/window/docks/program_dock.py" line="+181"/>
        <source>program %1 refused: %2</source>
        <translation>programme %1 refusé&#xa0;: %2</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>only programs of points (CSV, JSON) are saved as JSON</source>
        <translation>seuls les programmes de points (CSV, JSON) s&apos;enregistrent en JSON</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>program %1 cannot run: %2</source>
        <translation>le programme %1 ne peut pas être exécuté&#xa0;: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>program %1: %2 segments, nothing sent yet</source>
        <translation>programme %1&#xa0;: %2 segments, rien n&apos;a encore été envoyé</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>the program has no moves</source>
        <translation>le programme ne contient aucun mouvement</translation>
    </message>
    <message>
        <location line="+93"/>
        <source>program saved to %1 (%2 points)</source>
        <translation>programme enregistré dans %1 (%2 points)</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>the program stopped: %1</source>
        <translation>le programme s&apos;est arrêté&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>program %1 done: %2/%3 executed in %4 s</source>
        <translation>programme %1 terminé&#xa0;: %2/%3 exécutées en %4 s</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>program %1 stopped: %2/%3 executed in %4 s</source>
        <translation>programme %1 arrêté&#xa0;: %2/%3 exécutées en %4 s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1; %2 frames, %3 retransmission(s)</source>
        <translation>%1&#xa0;; %2 trames, %3 retransmission(s)</translation>
    </message>
</context>
<context>
    <name>ProgramPanel</name>
    <message>
        <source>Programs (*.csv *.json);;All files (*)</source>
        <translation type="vanished">Programmes (*.csv *.json);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <location filename="../../widgets/program_panel.py" line="+39"/>
        <source>no program loaded</source>
        <translation>aucun programme chargé</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation type="vanished">Charger…</translation>
    </message>
    <message>
        <source>Load a program: CSV with x,y,z,speed (mm, mm/s) or JSON</source>
        <translation type="vanished">Charger un programme&#xa0;: CSV avec x,y,z,speed (mm, mm/s) ou JSON</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Save…</source>
        <translation>Enregistrer…</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Save the loaded program as JSON (x, y, z, speed per point)</source>
        <translation>Enregistrer le programme chargé en JSON (x, y, z, speed par point)</translation>
    </message>
    <message>
        <source>Run</source>
        <translation type="vanished">Exécuter</translation>
    </message>
    <message>
        <source>Stream the program to the device, 7 moves a frame</source>
        <translation type="vanished">Envoyer le programme en continu à l&apos;appareil, 7 mouvements par trame</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="vanished">Pause</translation>
    </message>
    <message>
        <source>Send nothing more until Resume (queued moves go on)</source>
        <translation type="vanished">Ne plus rien envoyer jusqu&apos;à Reprendre (les mouvements en file se poursuivent)</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="vanished">Arrêt</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>&amp;Load…</source>
        <translation>&amp;Charger…</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&amp;Run</source>
        <translation>Exécute&amp;r</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+366"/>
        <source>P&amp;ause</source>
        <translation>Pa&amp;use</translation>
    </message>
    <message>
        <location line="-363"/>
        <source>&amp;Stop</source>
        <translation>Arrê&amp;t</translation>
    </message>
    <message>
        <source>Send nothing more and flush the device&apos;s queue (STOP)</source>
        <translation type="vanished">Ne plus rien envoyer et vider la file de l&apos;appareil (STOP)</translation>
    </message>
    <message>
        <location line="-55"/>
        <source>Programs (*.gcode *.nc *.ngc *.tap *.dxf *.svg *.csv *.json);;G-code (*.gcode *.nc *.ngc *.tap);;DXF drawings (*.dxf);;SVG drawings (*.svg);;Points (*.csv *.json);;All files (*)</source>
        <translation>Programmes (*.gcode *.nc *.ngc *.tap *.dxf *.svg *.csv *.json);;G-code (*.gcode *.nc *.ngc *.tap);;Dessins DXF (*.dxf);;Dessins SVG (*.svg);;Points (*.csv *.json);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Load a program: G-code, DXF or SVG, or points (CSV with x,y,z,speed in mm and mm/s, or JSON)</source>
        <translation>Charger un programme&#xa0;: G-code, DXF ou SVG, ou des points (CSV avec x,y,z,vitesse en mm et mm/s, ou JSON)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Run the program on the device (checked against the box first)</source>
        <translation>Exécuter le programme sur l&apos;appareil (vérifié d&apos;abord par rapport à la zone)</translation>
    </message>
    <message>
        <location line="+351"/>
        <source>Send nothing more until Resume (a device&apos;s queued moves go on)</source>
        <translation>Ne plus rien envoyer jusqu&apos;à Reprendre (les mouvements en file de l&apos;appareil se poursuivent)</translation>
    </message>
    <message>
        <location line="-344"/>
        <source>Send nothing more and stop the device (its queue flushed)</source>
        <translation>Ne plus rien envoyer et arrêter l&apos;appareil (sa file est vidée)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Chord tolerance: how far the straight moves an arc or curve is cut into may stray from it</source>
        <translation>Tolérance de corde&#xa0;: écart permis entre un arc ou une courbe et les mouvements rectilignes qui le découpent</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Instructions executed by the device</source>
        <translation>Instructions exécutées par l&apos;appareil</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+137"/>
        <source>%v / %m executed</source>
        <translation>%v / %m exécutées</translation>
    </message>
    <message>
        <location line="-117"/>
        <source>The program&apos;s lines; the one under way is highlighted</source>
        <translation>Les lignes du programme&#xa0;; celle en cours est surlignée</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The drawing&apos;s layers: the checked ones are run</source>
        <translation>Les calques du dessin&#xa0;: les calques cochés sont exécutés</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Program:</source>
        <translation>Programme&#xa0;:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Chord tolerance:</source>
        <translation>Tolérance de corde&#xa0;:</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Load a program</source>
        <translation>Charger un programme</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Save the program</source>
        <translation>Enregistrer le programme</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>JSON (*.json)</source>
        <translation>JSON (*.json)</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>reading %1…</source>
        <translation>lecture de %1…</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 (%2 lines)</source>
        <translation>%1 (%2 lignes)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (%2 entities)</source>
        <translation>%1 (%2 entités)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (%2 elements)</source>
        <translation>%1 (%2 éléments)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2 points)</source>
        <translation>%1 (%2 points)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>no program</source>
        <translation>aucun programme</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>line %1</source>
        <translation>ligne %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>entity %1</source>
        <translation>entité %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>element %1</source>
        <translation>élément %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point %1</source>
        <translation>point %1</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>length %1 mm (travel moves %2 mm), %3 segments</source>
        <translation>longueur %1 mm (déplacements à vide %2 mm), %3 segments</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>box X %1 to %2, Y %3 to %4, Z %5 to %6 mm</source>
        <translation>zone X de %1 à %2, Y de %3 à %4, Z de %5 à %6 mm</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>about %1 (h:mm:ss) at %2 mm/s where the program sets no speed</source>
        <translation>environ %1 (h:mm:ss) à %2 mm/s là où le programme ne fixe pas de vitesse</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>%1
Not for this program: %2</source>
        <translation>%1
Non applicable à ce programme&#xa0;: %2</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>not connected to a device</source>
        <translation>non connecté à un appareil</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>motion is off</source>
        <translation>les mouvements sont désactivés</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1
Refused: %2</source>
        <translation>%1
Refusé&#xa0;: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1
Not now: %2</source>
        <translation>%1
Indisponible pour le moment&#xa0;: %2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Send nothing more until Resume. This device has no feed hold: it goes on running the moves it already holds (the status line says how many, and when it stands still); Stop flushes them</source>
        <translation>Ne plus rien envoyer jusqu&apos;à Reprendre. Cet appareil n&apos;a pas de suspension d&apos;avance&#xa0;: il continue d&apos;exécuter les mouvements qu&apos;il contient déjà (la ligne d&apos;état indique combien, et quand il sera immobile)&#xa0;; Arrêt les annule</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Send nothing more until Resume. The move under way finishes, then the stage stands still (this device has no feed hold)</source>
        <translation>Ne plus rien envoyer jusqu&apos;à Reprendre. Le mouvement en cours se termine, puis la platine s&apos;immobilise (cet appareil n&apos;a pas de suspension d&apos;avance)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Resume</source>
        <translation>Reprendre</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>, paused</source>
        <translation>, en pause</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, about %1 s left</source>
        <translation>, reste environ %1 s</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>sent %1, acknowledged %2, executed %3; %4 instructions/s%5; %6 retransmission(s)</source>
        <translation>%1 envoyées, %2 acquittées, %3 exécutées&#xa0;; %4 instructions/s%5&#xa0;; %6 retransmission(s)</translation>
    </message>
</context>
<context>
    <name>RawConsole</name>
    <message>
        <location filename="../../app/window/console/display.py" line="+16"/>
        <source>text</source>
        <translation>texte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hex</source>
        <translation>hex</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mixed</source>
        <translation>mixte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>relative</source>
        <translation>relatif</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>absolute</source>
        <translation>absolu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>delta</source>
        <translation>delta</translation>
    </message>
    <message>
        <location filename="../../app/window/console/export.py" line="+18"/>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Text (*.txt)</source>
        <translation>Texte (*.txt)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>All files (*)</source>
        <translation>Tous les fichiers (*)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export traffic</source>
        <translation>Exporter le trafic</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>exported %1 line to %2</source>
        <translation>%1 ligne exportée vers %2</translation>
    </message>
    <message>
        <location filename="../../app/window/console/display.py" line="+26"/>
        <source>Bytes as text (\r \n \xNN escapes), hex (47 45 54), or mixed (text, &lt;0A&gt; for the rest)</source>
        <translation>Octets en texte (échappements \r \n \xNN), en hex (47 45 54) ou en mixte (texte, &lt;0A&gt; pour le reste)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Times: seconds since the session start, wall-clock time, or the gap since the line above</source>
        <translation>Temps&#xa0;: secondes depuis le début de la session, heure de l&apos;horloge, ou écart avec la ligne précédente</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Time</source>
        <translation>Temps</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Show the time column</source>
        <translation>Afficher la colonne du temps</translation>
    </message>
    <message>
        <location filename="../../app/window/console/filter_bar.py" line="+57"/>
        <source>TX</source>
        <translation>TX</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show what was sent to the device</source>
        <translation>Afficher ce qui a été envoyé à l&apos;appareil</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>RX</source>
        <translation>RX</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show what the device sent</source>
        <translation>Afficher ce que l&apos;appareil a envoyé</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Kinds</source>
        <translation>Types</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Which kinds of lines to show</source>
        <translation>Types de lignes à afficher</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Poll</source>
        <translation>Interrogation</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Show the idle position queries and their replies (hidden by default; counted below)</source>
        <translation>Afficher les interrogations de position au repos et leurs réponses (masquées par défaut&#xa0;; comptées ci-dessous)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>filter (regex)</source>
        <translation>filtre (regex)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Show only lines matching this regular expression (case-insensitive) in their direction, kind, hex, text or meaning, e.g. error|FA00</source>
        <translation>N&apos;afficher que les lignes dont le sens, le type, l&apos;hex, le texte ou la signification correspondent à cette expression régulière (sans tenir compte de la casse), par ex. error|FA00</translation>
    </message>
    <message>
        <location filename="../../app/window/console/traffic_console.py" line="+124"/>
        <source>paused</source>
        <translation>en pause</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>New lines do not scroll the view: scroll to the bottom to follow</source>
        <translation>Les nouvelles lignes ne font pas défiler la vue&#xa0;: faire défiler jusqu&apos;en bas pour suivre</translation>
    </message>
    <message>
        <location filename="../../app/window/console/filter_bar.py" line="+12"/>
        <source>search (regex)</source>
        <translation>rechercher (regex)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Highlight matching lines; Enter or F3: next, Shift+F3: previous</source>
        <translation>Surligner les lignes correspondantes&#xa0;; Entrée ou F3&#xa0;: suivante, Maj+F3&#xa0;: précédente</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Previous match (Shift+F3)</source>
        <translation>Correspondance précédente (Maj+F3)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Next match (F3)</source>
        <translation>Correspondance suivante (F3)</translation>
    </message>
    <message>
        <location filename="../../app/window/console/status.py" line="+45"/>
        <source>Lines in the session, shown, hidden polls, errors, matches</source>
        <translation>Lignes de la session, affichées, interrogations masquées, erreurs, correspondances</translation>
    </message>
    <message>
        <location filename="../../app/window/console/traffic_console.py" line="+18"/>
        <source>Export…</source>
        <translation>Exporter…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save the lines shown (filtered) as text or CSV</source>
        <translation>Enregistrer les lignes affichées (filtrées) en texte ou en CSV</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Clear</source>
        <translation>Effacer</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Forget the lines (the session log keeps them)</source>
        <translation>Oublier les lignes (le journal de session les conserve)</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>TX (blue): sent to the device; RX (green): received; grey: notes and the device&apos;s own text; red: errors. Double-click a line to go to its request, reply or first copy.</source>
        <translation>TX (bleu)&#xa0;: envoyé à l&apos;appareil&#xa0;; RX (vert)&#xa0;: reçu&#xa0;; gris&#xa0;: notes et texte propre à l&apos;appareil&#xa0;; rouge&#xa0;: erreurs. Double-cliquer sur une ligne pour aller à sa requête, à sa réponse ou à sa première copie.</translation>
    </message>
    <message>
        <location line="+102"/>
        <source>the console keeps the newest %1 lines: older lines are dropped from it as new ones come; the session log keeps every line</source>
        <translation>la console conserve les %1 lignes les plus récentes&#xa0;: les plus anciennes en sont retirées à mesure que de nouvelles arrivent&#xa0;; le journal de session conserve toutes les lignes</translation>
    </message>
    <message>
        <location line="+133"/>
        <source>line %1 is no longer in the console (its line limit dropped it); the session log has it</source>
        <translation>la ligne %1 n&apos;est plus dans la console (retirée par sa limite de lignes)&#xa0;; le journal de session la contient</translation>
    </message>
    <message>
        <source>%1 lines reached the console&apos;s limit and were cleared; the session log keeps them</source>
        <translation type="vanished">%1 lignes ont atteint la limite de la console et ont été effacées&#xa0;; le journal de session les conserve</translation>
    </message>
    <message>
        <location filename="../../app/window/console/status.py" line="+16"/>
        <source>%1 line</source>
        <translation>%1 ligne</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 lines</source>
        <translation>%1 lignes</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 shown</source>
        <translation>%1 affichées</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 older in the session log</source>
        <translation>%1 plus anciennes dans le journal de session</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 poll hidden</source>
        <translation>%1 interrogations masquées</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 error</source>
        <translation>%1 erreur</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 errors</source>
        <translation>%1 erreurs</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 match</source>
        <translation>%1 correspondance</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 matches</source>
        <translation>%1 correspondances</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 more hidden by the filters</source>
        <translation>%1 de plus masquées par les filtres</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The console keeps the newest %1 lines (Settings): older lines are dropped from it, the session log on disk keeps every line</source>
        <translation>La console conserve les %1 lignes les plus récentes (Réglages)&#xa0;: les plus anciennes en sont retirées, le journal de session sur disque conserve toutes les lignes</translation>
    </message>
    <message>
        <location filename="../../app/window/console/traffic_console.py" line="+114"/>
        <source>export failed: %1</source>
        <translation>échec de l&apos;export&#xa0;: %1</translation>
    </message>
    <message>
        <location filename="../../app/window/console/export.py" line="+2"/>
        <source>exported %1 lines to %2</source>
        <translation>%1 lignes exportées vers %2</translation>
    </message>
    <message>
        <location filename="../../app/window/console/table.py" line="+60"/>
        <source>motion</source>
        <translation>mouvement</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>query</source>
        <translation>requête</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>poll</source>
        <translation>interrogation</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>setting</source>
        <translation>réglage</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error</source>
        <translation>erreur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>debug</source>
        <translation>débogage</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>note</source>
        <translation>note</translation>
    </message>
</context>
<context>
    <name>SendLine</name>
    <message>
        <location filename="../../widgets/send_line.py" line="+19"/>
        <source>text</source>
        <translation>texte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hex</source>
        <translation>hex</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>none</source>
        <translation>aucune</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>text: UTF-8 with \r \n \t \0 \\ \xNN escapes, plus the line ending;
hex: bytes like 48 45 4C 4C 4F, sent as they are</source>
        <translation>texte&#xa0;: UTF-8 avec les échappements \r \n \t \0 \\ \xNN, plus la fin de ligne&#xa0;;
hex&#xa0;: octets comme 48 45 4C 4C 4F, envoyés tels quels</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Appended to every line sent in text mode</source>
        <translation>Ajoutée à chaque ligne envoyée en mode texte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send</source>
        <translation>Envoyer</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Send the line to the device (Enter)</source>
        <translation>Envoyer la ligne à l&apos;appareil (Entrée)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Sen&amp;d:</source>
        <translation>E&amp;nvoyer&#xa0;:</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>hex bytes, e.g. 48 45 4C 4C 4F (Up/Down: history)</source>
        <translation>octets hex, par ex. 48 45 4C 4C 4F (Haut/Bas&#xa0;: historique)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>text to send (Up/Down: history)</source>
        <translation>texte à envoyer (Haut/Bas&#xa0;: historique)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>nothing to send</source>
        <translation>rien à envoyer</translation>
    </message>
</context>
<context>
    <name>SettingsDialog</name>
    <message>
        <location filename="../../widgets/settings_dialog.py" line="+78"/>
        <source>Settings</source>
        <translation>Réglages</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Connection</source>
        <translation>Connexion</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Console &amp;&amp; log</source>
        <translation>Console &amp;&amp; journal</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Display</source>
        <translation>Affichage</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Keyboard jog</source>
        <translation>Clavier</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Appearance &amp;&amp; language</source>
        <translation>Apparence &amp;&amp; langue</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Use and save</source>
        <translation>Appliquer et enregistrer</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Use and save, and keep this open</source>
        <translation>Appliquer et enregistrer, sans fermer la fenêtre</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Put every field back to its default (saved only with OK or Apply)</source>
        <translation>Remettre chaque champ à sa valeur par défaut (enregistré seulement avec OK ou Appliquer)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Close without saving</source>
        <translation>Fermer sans enregistrer</translation>
    </message>
    <message>
        <location line="+103"/>
        <source>Position polling</source>
        <translation>Interrogation de la position</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>How often the position is read while a move is being confirmed, in hertz (%1 to %2 Hz). Faster confirms the end of each jog step sooner; above 20 Hz nothing is seen sooner.</source>
        <translation>Fréquence de lecture de la position pendant la confirmation d&apos;un mouvement, en hertz (%1 à %2 Hz). Plus elle est élevée, plus la fin de chaque pas de déplacement est confirmée tôt&#xa0;; au-delà de 20 Hz, rien n&apos;est vu plus tôt.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Poll while moving:</source>
        <translation>Interrogation en mouvement&#xa0;:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Seconds between position reads while nothing moves (%1 to %2 s). This is also how a device that restarted or stopped answering is noticed.</source>
        <translation>Secondes entre deux lectures de la position au repos (%1 à %2 s). C&apos;est aussi ainsi qu&apos;est détecté un appareil qui a redémarré ou ne répond plus.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Poll when idle:</source>
        <translation>Interrogation au repos&#xa0;:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Console</source>
        <translation>Console</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> lines</source>
        <translation> lignes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep every line</source>
        <translation>Conserver toutes les lignes</translation>
    </message>
    <message>
        <source>The most lines the console keeps: 0 keeps every line (a spool file on disk and about 33 bytes a line in memory), else %1 to %2 lines. The session log keeps every byte either way.</source>
        <translation type="vanished">Nombre maximal de lignes conservées par la console&#xa0;: 0 les conserve toutes (un fichier tampon sur disque et environ 33 octets par ligne en mémoire), sinon de %1 à %2 lignes. Le journal de session conserve chaque octet dans tous les cas.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The most lines the console keeps: 0 keeps every line (a spool file on disk and about 33 bytes a line in memory), else %1 to %2 lines, the oldest dropped as new ones come. The session log keeps every byte either way.</source>
        <translation>Nombre maximal de lignes conservées par la console&#xa0;: 0 les conserve toutes (un fichier tampon sur disque et environ 33 octets par ligne en mémoire), sinon de %1 à %2 lignes, les plus anciennes étant retirées à mesure que de nouvelles arrivent. Dans tous les cas, le journal de session conserve chaque octet.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Console lines kept:</source>
        <translation>Lignes de console conservées&#xa0;:</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Session log</source>
        <translation>Journal de session</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write every byte of every session to a file</source>
        <translation>Écrire chaque octet de chaque session dans un fichier</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>One file a session in the log folder; the oldest go beyond 200 MiB</source>
        <translation>Un fichier par session dans le dossier des journaux&#xa0;; les plus anciens sont supprimés au-delà de 200 MiB</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the app-data folder</source>
        <translation>le dossier de données de l&apos;application</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Default: %1</source>
        <translation>Par défaut&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>An absolute path to a folder you can write to; empty: the default folder</source>
        <translation>Chemin absolu d&apos;un dossier accessible en écriture&#xa0;; vide&#xa0;: le dossier par défaut</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Browse…</source>
        <translation>Parcourir…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose the session log folder</source>
        <translation>Choisir le dossier du journal de session</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Session log folder:</source>
        <translation>Dossier du journal de session&#xa0;:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Positions</source>
        <translation>Positions</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Millimetres (mm)</source>
        <translation>Millimètres (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Inches (in)</source>
        <translation>Pouces (in)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The unit positions are shown in; the device is always sent millimetres</source>
        <translation>L&apos;unité d&apos;affichage des positions&#xa0;; l&apos;appareil reçoit toujours des millimètres</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Units shown:</source>
        <translation>Unités affichées&#xa0;:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> decimals</source>
        <translation> décimales</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>As the device resolves</source>
        <translation>Selon la résolution de l&apos;appareil</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Decimals of the positions shown (%1 to %2), or as many as the device resolves (0.01 mm: 2)</source>
        <translation>Décimales des positions affichées (%1 à %2), ou autant que la résolution de l&apos;appareil (0.01 mm&#xa0;: 2)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Decimals shown:</source>
        <translation>Décimales affichées&#xa0;:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Travel limits</source>
        <translation>Limites de course</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clamp a move to the limits instead of refusing it</source>
        <translation>Borner un mouvement aux limites au lieu de le refuser</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>What a device starts with until its own limits are saved</source>
        <translation>Réglage initial d&apos;un appareil tant que ses propres limites ne sont pas enregistrées</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Each device&apos;s box is set in Motion → Travel limits…</source>
        <translation>La zone de chaque appareil se règle dans Mouvement → Limites de course…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Jog keys</source>
        <translation>Touches de déplacement</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>X-:</source>
        <translation>X-&#xa0;:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog X down by one step</source>
        <translation>Déplacer X d&apos;un pas dans le sens négatif</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X+:</source>
        <translation>X+&#xa0;:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog X up by one step</source>
        <translation>Déplacer X d&apos;un pas dans le sens positif</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y-:</source>
        <translation>Y-&#xa0;:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog Y down by one step</source>
        <translation>Déplacer Y d&apos;un pas dans le sens négatif</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y+:</source>
        <translation>Y+&#xa0;:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog Y up by one step</source>
        <translation>Déplacer Y d&apos;un pas dans le sens positif</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z-:</source>
        <translation>Z-&#xa0;:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog Z down by one step</source>
        <translation>Déplacer Z d&apos;un pas dans le sens négatif</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z+:</source>
        <translation>Z+&#xa0;:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog Z up by one step</source>
        <translation>Déplacer Z d&apos;un pas dans le sens positif</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Smaller step:</source>
        <translation>Pas plus petit&#xa0;:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The next smaller step</source>
        <translation>Le pas immédiatement inférieur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Larger step:</source>
        <translation>Pas plus grand&#xa0;:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The next larger step</source>
        <translation>Le pas immédiatement supérieur</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Click, then press one key (no Shift, Ctrl, Alt or Meta)</source>
        <translation>Cliquer, puis appuyer sur une touche (sans Maj, Ctrl, Alt ni Méta)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Shift with a jog key makes the step ten times bigger. Esc (Stop), Tab, Enter, Space and F3 are the window&apos;s own.</source>
        <translation>Maj avec une touche de déplacement multiplie le pas par dix. Échap (Arrêt), Tab, Entrée, Espace et F3 sont réservées à la fenêtre.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Appearance and language</source>
        <translation>Apparence et langue</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+10"/>
        <source>As the system</source>
        <translation>Comme le système</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>Light</source>
        <translation>Clair</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dark</source>
        <translation>Sombre</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light or dark colours, or those of the desktop</source>
        <translation>Couleurs claires ou sombres, ou celles du bureau</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Theme:</source>
        <translation>Thème&#xa0;:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>English</source>
        <translation>English</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Español</source>
        <translation>Español</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Français</source>
        <translation>Français</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>简体中文</source>
        <translation>简体中文</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The interface&apos;s language; --lang and $MOTIONPANEL_LANG come first</source>
        <translation>La langue de l&apos;interface&#xa0;; --lang et $MOTIONPANEL_LANG sont prioritaires</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Language:</source>
        <translation>Langue&#xa0;:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A new language shows when the panel next starts.</source>
        <translation>Une nouvelle langue s&apos;applique au prochain démarrage du panneau.</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>%1: %2 is not a number from %3 to %4 %5</source>
        <translation>%1&#xa0;: %2 n&apos;est pas un nombre de %3 à %4 %5</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Memory grows with the session: about 33 MB a million lines.</source>
        <translation>La mémoire croît avec la session&#xa0;: environ 33 MB par million de lignes.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>About %1 MB of memory at most.</source>
        <translation>Environ %1 MB de mémoire au maximum.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Session log folder</source>
        <translation>Dossier du journal de session</translation>
    </message>
</context>
<context>
    <name>ShortcutsDialog</name>
    <message>
        <location filename="../../widgets/shortcuts_dialog.py" line="+75"/>
        <source>Keyboard Shortcuts</source>
        <translation>Raccourcis clavier</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Search shortcuts…</source>
        <translation>Rechercher des raccourcis…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Search shortcuts</source>
        <translation>Rechercher des raccourcis</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Keys</source>
        <translation>Touches</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Action</source>
        <translation>Action</translation>
    </message>
    <message>
        <location line="+77"/>
        <source>No shortcut matches “%1”.</source>
        <translation>Aucun raccourci ne correspond à «&#xa0;%1&#xa0;».</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No keyboard shortcuts.</source>
        <translation>Aucun raccourci clavier.</translation>
    </message>
</context>
<context>
    <name>SpeedControl</name>
    <message>
        <location filename="../../widgets/speed_control.py" line="+53"/>
        <source>Speed:</source>
        <translation>Vitesse&#xa0;:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed of the next moves</source>
        <translation>Vitesse des prochains mouvements</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Apply</source>
        <translation>Appliquer</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+45"/>
        <source>Send the speed in the field to the device</source>
        <translation>Envoyer à l&apos;appareil la vitesse saisie</translation>
    </message>
    <message>
        <location line="-40"/>
        <source>The speed the device reports (it may round)</source>
        <translation>La vitesse indiquée par l&apos;appareil (il peut l&apos;arrondir)</translation>
    </message>
    <message>
        <location line="+122"/>
        <source>Speed, %1 to %2 in/s; press Enter or Apply to send</source>
        <translation>Vitesse, de %1 à %2 in/s&#xa0;; appuyer sur Entrée ou Appliquer pour envoyer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag and release to send (%1 to %2 in/s)</source>
        <translation>Faire glisser puis relâcher pour envoyer (%1 à %2 in/s)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Speed, %1 to %2 mm/s; press Enter or Apply to send</source>
        <translation>Vitesse, de %1 à %2 mm/s&#xa0;; appuyer sur Entrée ou Appliquer pour envoyer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag and release to send (%1 to %2 mm/s)</source>
        <translation>Faire glisser puis relâcher pour envoyer (%1 à %2 mm/s)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>device: %1 in/s</source>
        <translation>appareil&#xa0;: %1 in/s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>device: %1 mm/s</source>
        <translation>appareil&#xa0;: %1 mm/s</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+3"/>
        <source>%1; nothing sent</source>
        <translation>%1&#xa0;; rien n&apos;a été envoyé</translation>
    </message>
</context>
<context>
    <name>StatusLine</name>
    <message>
        <location filename="../../widgets/status_line.py" line="+19"/>
        <source>Disconnected</source>
        <translation>Déconnecté</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No device is connected</source>
        <translation>Aucun appareil n&apos;est connecté</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+47"/>
        <source>Connecting…</source>
        <translation>Connexion…</translation>
    </message>
    <message>
        <location line="-45"/>
        <source>Opening the port and asking the device who it is</source>
        <translation>Ouverture du port et identification de l&apos;appareil</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Idle</source>
        <translation>Au repos</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Connected and not moving</source>
        <translation>Connecté et immobile</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Moving</source>
        <translation>En mouvement</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A move is under way</source>
        <translation>Un mouvement est en cours</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Busy</source>
        <translation>Occupé</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A command is under way</source>
        <translation>Une commande est en cours</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Paused</source>
        <translation>En pause</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A program is paused: nothing more of it is sent until Resume</source>
        <translation>Un programme est en pause&#xa0;: plus rien n&apos;en est envoyé jusqu&apos;à Reprendre</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Error</source>
        <translation>Erreur</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The last command failed, or the connection did</source>
        <translation>La dernière commande a échoué, ou bien la connexion</translation>
    </message>
</context>
<context>
    <name>ThemeMenu</name>
    <message>
        <location filename="../../app/window/theme.py" line="+373"/>
        <source>&amp;Theme</source>
        <translation>&amp;Thème</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Follow the &amp;system</source>
        <translation>Suivre le &amp;système</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Light</source>
        <translation>&amp;Clair</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Dark</source>
        <translation>&amp;Sombre</translation>
    </message>
</context>
<context>
    <name>TrafficFormat</name>
    <message>
        <location filename="../../widgets/traffic_format.py" line="+38"/>
        <source>\x needs two hex digits at column %1: %2</source>
        <translation>\x nécessite deux chiffres hex à la colonne %1&#xa0;: %2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>a lone backslash ends the line: write \\ for a backslash</source>
        <translation>une barre oblique inverse seule termine la ligne&#xa0;: écrire \\ pour une barre oblique inverse</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>unknown escape \%1 at column %2 (use \r \n \t \0 \\ \xNN)</source>
        <translation>échappement inconnu \%1 à la colonne %2 (utiliser \r \n \t \0 \\ \xNN)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>not hex: %1</source>
        <translation>hex invalide&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>odd number of hex digits in %1: write 0%2 or pairs</source>
        <translation>nombre impair de chiffres hex dans %1&#xa0;: écrire 0%2 ou des paires</translation>
    </message>
</context>
<context>
    <name>TrafficModel</name>
    <message>
        <location filename="../../app/window/console/table.py" line="-21"/>
        <source>Line</source>
        <translation>Ligne</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time</source>
        <translation>Temps</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dir</source>
        <translation>Sens</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bytes</source>
        <translation>Octets</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Meaning</source>
        <translation>Signification</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reply</source>
        <translation>Réponse</translation>
    </message>
    <message>
        <location line="+316"/>
        <source>line %1: %2</source>
        <translation>ligne %1&#xa0;: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>hex: %1</source>
        <translation>hex&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>text: %1</source>
        <translation>texte&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 (double-click to go there)</source>
        <translation>%1 (double-cliquer pour y aller)</translation>
    </message>
</context>
<context>
    <name>TrafficTimeline</name>
    <message>
        <location filename="../../widgets/timeline/plots.py" line="+20"/>
        <source>TX</source>
        <translation>TX</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RX</source>
        <translation>RX</translation>
    </message>
    <message>
        <location filename="../../widgets/traffic_timeline.py" line="+85"/>
        <source>Follow</source>
        <translation>Suivre</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Keep the latest %1 s in view; zooming or panning stops it</source>
        <translation>Garder à l&apos;écran les %1 s les plus récentes&#xa0;; zoomer ou déplacer la vue l&apos;interrompt</translation>
    </message>
    <message>
        <location filename="../../widgets/timeline/plots.py" line="+32"/>
        <source>Bytes per second each way, in one-second bins: TX (blue) sent to the device, RX (green) received. Click a bin to show its first line in the console.</source>
        <translation>Octets par seconde dans chaque sens, par tranches d&apos;une seconde&#xa0;: TX (bleu) envoyés à l&apos;appareil, RX (vert) reçus. Cliquer sur une tranche pour afficher sa première ligne dans la console.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>rate</source>
        <translation>débit</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Bytes per second</source>
        <translation>Octets par seconde</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Command latency</source>
        <translation>Latence des commandes</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Time from a request to its reply, in ms: one point per answered request (drawn as dots when few are in view). Click a point to show its line in the console.</source>
        <translation>Temps entre une requête et sa réponse, en ms&#xa0;: un point par requête ayant reçu une réponse (dessinés isolément quand peu sont visibles). Cliquer sur un point pour afficher sa ligne dans la console.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>latency</source>
        <translation>latence</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>time since the session started</source>
        <translation>temps écoulé depuis le début de la session</translation>
    </message>
</context>
<context>
    <name>TravelLimitsDialog</name>
    <message>
        <location filename="../../widgets/travel_limits_dialog.py" line="+19"/>
        <source>Travel limits</source>
        <translation>Limites de course</translation>
    </message>
    <message>
        <source>Where the stage may go on %1. A jog, go-to or command-line move that would leave the box is refused before anything is sent, or clamped to its edge.</source>
        <translation type="vanished">Zone où la platine peut se déplacer sur %1. Un déplacement pas à pas, un «&#xa0;Aller à&#xa0;» ou un mouvement en ligne de commande qui sortirait de la zone est refusé avant tout envoi, ou borné à sa limite.</translation>
    </message>
    <message>
        <source>Limit moves to this box</source>
        <translation type="vanished">Limiter les mouvements à cette zone</translation>
    </message>
    <message>
        <source>min</source>
        <translation type="vanished">min</translation>
    </message>
    <message>
        <source>max</source>
        <translation type="vanished">max</translation>
    </message>
    <message>
        <source>%1:</source>
        <comment>an axis field&apos;s label</comment>
        <translation type="vanished">%1&#xa0;:</translation>
    </message>
    <message>
        <source>%1 min</source>
        <comment>an axis&apos; lower travel limit</comment>
        <translation type="vanished">%1 min</translation>
    </message>
    <message>
        <source>%1 max</source>
        <comment>an axis&apos; upper travel limit</comment>
        <translation type="vanished">%1 max</translation>
    </message>
    <message>
        <source>Refuse a move that would leave the box</source>
        <translation type="vanished">Refuser un mouvement qui sortirait de la zone</translation>
    </message>
    <message>
        <source>Clamp it: go as far as the edge, and say so</source>
        <translation type="vanished">Le borner&#xa0;: aller jusqu&apos;à la limite, et le signaler</translation>
    </message>
    <message>
        <source>%1: the minimum must be below the maximum</source>
        <translation type="vanished">%1&#xa0;: le minimum doit être inférieur au maximum</translation>
    </message>
</context>
<context>
    <name>TravelLimitsForm</name>
    <message>
        <location filename="../../widgets/travel_limits_form.py" line="+45"/>
        <source>Limit moves to this box</source>
        <translation>Limiter les mouvements à cette zone</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max</source>
        <translation>max</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1:</source>
        <comment>an axis field&apos;s label</comment>
        <translation>%1&#xa0;:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 min</source>
        <comment>an axis&apos; lower travel limit</comment>
        <translation>%1 min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 max</source>
        <comment>an axis&apos; upper travel limit</comment>
        <translation>%1 max</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Refuse a move that would leave the box</source>
        <translation>Refuser un mouvement qui sortirait de la zone</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Clamp it: go as far as the edge, and say so</source>
        <translation>Le borner&#xa0;: aller jusqu&apos;à la limite, et le signaler</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Where the stage may go on %1. A jog, go-to or command-line move that would leave the box is refused before anything is sent, or clamped to its edge.</source>
        <translation>Zone où la platine peut se déplacer sur %1. Un déplacement pas à pas, un «&#xa0;Aller à&#xa0;» ou un mouvement en ligne de commande qui sortirait de la zone est refusé avant tout envoi, ou borné à sa limite.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Connect a device to set where its stage may go.</source>
        <translation>Connecter un appareil pour définir où sa platine peut se déplacer.</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>%1: the minimum must be below the maximum</source>
        <translation>%1&#xa0;: le minimum doit être inférieur au maximum</translation>
    </message>
</context>
<context>
    <name>TravelLimitsPanel</name>
    <message>
        <location line="+25"/>
        <source>Apply</source>
        <translation>Appliquer</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Use these limits for this device from now on (kept for it)</source>
        <translation>Utiliser désormais ces limites pour cet appareil (conservées pour lui)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Revert</source>
        <translation>Rétablir</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Show the limits in use again</source>
        <translation>Afficher de nouveau les limites en vigueur</translation>
    </message>
</context>
<context>
    <name>UnitSpinBox</name>
    <message>
        <location filename="../../widgets/_units.py" line="+22"/>
        <source>in/s</source>
        <comment>inches per second</comment>
        <translation>in/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>in</source>
        <comment>inches</comment>
        <translation>in</translation>
    </message>
</context>
<context>
    <name>ValueDelegate</name>
    <message>
        <location filename="../../widgets/parameter_table.py" line="-106"/>
        <source>%1: edit cancelled, value unchanged</source>
        <translation>%1&#xa0;: modification annulée, valeur inchangée</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 is an output. %2</source>
        <translation>%1 est une sortie. %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2</source>
        <translation>%1&#xa0;: %2</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1 = %2, not yet written to the device</source>
        <translation>%1 = %2, pas encore écrit sur l&apos;appareil</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1. Warning: %2</source>
        <translation>%1. Avertissement&#xa0;: %2</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1: %2 (Enter keeps it, Escape cancels)</source>
        <translation>%1&#xa0;: %2 (Entrée pour valider, Échap pour annuler)</translation>
    </message>
</context>
<context>
    <name>ViewTabs</name>
    <message>
        <location filename="../../widgets/view_tabs.py" line="+31"/>
        <source>3D</source>
        <translation>3D</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>XY and time</source>
        <translation>XY et temps</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The path in 3D</source>
        <translation>Le chemin en 3D</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The path seen from above and X, Y, Z against time</source>
        <translation>Le chemin vu de dessus et X, Y, Z en fonction du temps</translation>
    </message>
</context>
<context>
    <name>WindowTools</name>
    <message>
        <location filename="../../app/window/window_tools.py" line="+48"/>
        <source>Macros</source>
        <translation>Macros</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>&amp;Settings…</source>
        <translation>&amp;Réglages…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Poll rates, console, log folder, units, jog keys, theme</source>
        <translation>Fréquences d&apos;interrogation, console, dossier des journaux, unités, touches de déplacement, thème</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Help</source>
        <translation>Aid&amp;e</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Keyboard shortcuts</source>
        <translation>&amp;Raccourcis clavier</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;About Motion Panel</source>
        <translation>À &amp;propos de Motion Panel</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>Jog X - / +</source>
        <translation>Déplacer X - / +</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jog Y - / +</source>
        <translation>Déplacer Y - / +</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jog Z - / +</source>
        <translation>Déplacer Z - / +</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shift + a jog key</source>
        <translation>Maj + une touche de déplacement</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog ten times the step</source>
        <translation>Déplacer de dix fois le pas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hold a jog key</source>
        <translation>maintenir une touche de déplacement</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Keep jogging until it is released</source>
        <translation>Déplacer en continu jusqu&apos;au relâchement</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Keys: %1/%2 X, %3/%4 Y, %5/%6 Z, Shift ×10</source>
        <translation>Touches&#xa0;: %1/%2 X, %3/%4 Y, %5/%6 Z, Maj ×10</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>, %1/%2 step</source>
        <translation>, %1/%2 pas</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>settings saved; the language from the next start</source>
        <translation>réglages enregistrés&#xa0;; la langue s&apos;appliquera au prochain démarrage</translation>
    </message>
    <message>
        <source>the session log from the next start</source>
        <translation type="vanished">le journal de session change au prochain démarrage</translation>
    </message>
    <message>
        <source>the language from the next start</source>
        <translation type="vanished">la langue change au prochain démarrage</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>settings saved</source>
        <translation>réglages enregistrés</translation>
    </message>
    <message>
        <source>settings saved; %1</source>
        <translation type="vanished">réglages enregistrés&#xa0;; %1</translation>
    </message>
</context>
<context>
    <name>WorkFrame</name>
    <message>
        <location filename="../../app/window/docks/work_frame.py" line="+59"/>
        <source>work coordinates: %1</source>
        <translation>coordonnées pièce&#xa0;: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>work zero not set: the position is unknown</source>
        <translation>zéro pièce non défini&#xa0;: la position est inconnue</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>work zero set at %1 %2 (machine)</source>
        <translation>zéro pièce défini à %1 %2 (machine)</translation>
    </message>
    <message>
        <source>work zero set at %1 mm (machine)</source>
        <translation type="vanished">zéro pièce défini à %1 mm (machine)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>work zero cleared: work coordinates are machine coordinates</source>
        <translation>zéro pièce effacé&#xa0;: les coordonnées pièce sont les coordonnées machine</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>work zero kept in place: %1</source>
        <translation>zéro pièce maintenu en place&#xa0;: %1</translation>
    </message>
</context>
<context>
    <name>messages</name>
    <message>
        <location filename="message_templates.py" line="+15"/>
        <source>to ({x:g}, {y:g}, {z:g}) mm</source>
        <translation>vers ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>to its target</source>
        <translation>vers sa cible</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: COXIRIS has no stop command; the device finishes the move under way {target} (a blocking sketch answers nothing until then) and then carries out what it had already received; motionctl sent nothing more</source>
        <translation>interrompu&#xa0;: COXIRIS n&apos;a pas de commande d&apos;arrêt&#xa0;; l&apos;appareil termine le mouvement en cours {target} (un sketch bloquant ne répond rien jusque-là), puis exécute ce qu&apos;il avait déjà reçu&#xa0;; motionctl n&apos;a rien envoyé de plus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: Visiomex has no stop command; the device carries out the move packet it was sent {target} (FP0001, its steps, then FA0001); motionctl sent nothing more</source>
        <translation>interrompu&#xa0;: Visiomex n&apos;a pas de commande d&apos;arrêt&#xa0;; l&apos;appareil exécute le paquet de mouvement {target} qui lui a été envoyé (FP0001, ses pas, puis FA0001)&#xa0;; motionctl n&apos;a rien envoyé de plus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: pi-frame has no stop command and sends no replies; the device carries out the frame it was sent {target}; motionctl sent nothing more</source>
        <translation>interrompu&#xa0;: pi-frame n&apos;a pas de commande d&apos;arrêt et n&apos;envoie aucune réponse&#xa0;; l&apos;appareil exécute la trame {target} qui lui a été envoyée&#xa0;; motionctl n&apos;a rien envoyé de plus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: Firmata has no stop command; the board finishes the step message under way (at most 16383 steps) and stops there; the move&apos;s later messages, if it had more, were not sent</source>
        <translation>interrompu&#xa0;: Firmata n&apos;a pas de commande d&apos;arrêt&#xa0;; la carte termine le message de pas en cours (16383 pas au plus) et s&apos;arrête là&#xa0;; les messages suivants du mouvement, s&apos;il en avait d&apos;autres, n&apos;ont pas été envoyés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: {protocol} has no stop command; the device finishes what it was sent; motionctl sent nothing more</source>
        <translation>interrompu&#xa0;: {protocol} n&apos;a pas de commande d&apos;arrêt&#xa0;; l&apos;appareil termine ce qui lui a été envoyé&#xa0;; motionctl n&apos;a rien envoyé de plus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted before the device was talked to: nothing was sent</source>
        <translation>interrompu avant tout dialogue avec l&apos;appareil&#xa0;: rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: {command} does not move the stage</source>
        <translation>interrompu&#xa0;: {command} ne déplace pas la platine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted before the move was sent: the stage does not move</source>
        <translation>interrompu avant l&apos;envoi du déplacement&#xa0;: la platine ne bouge pas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted again while stopping: the {protocol} stop may not have arrived; the device may still be moving</source>
        <translation>interrompu à nouveau pendant l&apos;arrêt&#xa0;: l&apos;arrêt {protocol} n&apos;est peut-être pas arrivé&#xa0;; l&apos;appareil est peut-être encore en mouvement</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: the {protocol} stop was sent but not acknowledged ({error}); the device may still be moving</source>
        <translation>interrompu&#xa0;: l&apos;arrêt {protocol} a été envoyé mais non acquitté ({error})&#xa0;; l&apos;appareil est peut-être encore en mouvement</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted again</source>
        <translation>interrompu à nouveau</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: stopped (the {protocol} stop was acknowledged; its queue is flushed); where the stage stopped could not be read: {error}</source>
        <translation>interrompu&#xa0;: arrêté (l&apos;arrêt {protocol} a été acquitté&#xa0;; sa file est vidée)&#xa0;; la position où la platine s&apos;est arrêtée n&apos;a pas pu être lue&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: stopped at ({x:g}, {y:g}, {z:g}) mm (the {protocol} stop was acknowledged; its queue is flushed)</source>
        <translation>interrompu&#xa0;: arrêté à ({x:g}, {y:g}, {z:g}) mm (l&apos;arrêt {protocol} a été acquitté&#xa0;; sa file est vidée)</translation>
    </message>
    <message>
        <location line="-17"/>
        <source>usage: {usage} (got {count} arguments)</source>
        <translation>usage&#xa0;: {usage} ({count} arguments reçus)</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>--force is for raw only</source>
        <translation>--force ne s&apos;applique qu&apos;à raw</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command} needs --port (the device to talk to)</source>
        <translation>{command} nécessite --port (l&apos;appareil avec lequel dialoguer)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command} needs --protocol ({choices})</source>
        <translation>{command} nécessite --protocol ({choices})</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>usage: {usage}</source>
        <translation>usage&#xa0;: {usage}</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>--kind {kind} refused: --kind is for jog only (move is in mm)</source>
        <translation>--kind {kind} refusé&#xa0;: --kind ne s&apos;applique qu&apos;à jog (move s&apos;exprime en mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>usage: {command} {axes} ({protocol} has {count} axes)</source>
        <translation>usage&#xa0;: {command} {axes} ({protocol} a {count} axes)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>--kind {kind} refused: {protocol} moves are {kinds}</source>
        <translation>--kind {kind} refusé&#xa0;: les mouvements {protocol} sont de type {kinds}</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>speed {speed:g} mm/s refused: the device allows {low:g} to {high:g} mm/s</source>
        <translation>vitesse {speed:g} mm/s refusée&#xa0;: l&apos;appareil accepte de {low:g} à {high:g} mm/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed {speed:g} mm/s refused ({error})</source>
        <translation>vitesse {speed:g} mm/s refusée ({error})</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>raw move to ({x:g}, {y:g}, {z:g}) mm</source>
        <translation>déplacement brut vers ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <source>{file} names no protocol (no connection note: a motionctl --log file or a spy:// capture has none): give --protocol</source>
        <translation type="vanished">{file} n&apos;indique aucun protocole (pas de note de connexion&#xa0;: un fichier motionctl --log ou une capture spy:// n&apos;en a pas)&#xa0;: indiquer --protocol</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>{file}: its connection note: {error}</source>
        <translation>{file}&#xa0;: sa note de connexion&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>its connection notes name {named}</source>
        <translation>ses notes de connexion indiquent {named}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>try another --protocol</source>
        <translation>essayer un autre --protocol</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nothing in {file} decodes as {protocol} ({count} records of traffic, none a {protocol} frame); {hint}</source>
        <translation>rien dans {file} ne se décode en {protocol} ({count} enregistrements de trafic, aucun n&apos;est une trame {protocol})&#xa0;; {hint}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SVG scale {value:g} refused: it must be above 0</source>
        <translation>échelle SVG {value:g} refusée&#xa0;: elle doit être supérieure à 0</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>macro {name} ({count} step)</source>
        <translation>macro {name} ({count} étape)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name} ({count} steps)</source>
        <translation>macro {name} ({count} étapes)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a macro needs a name</source>
        <translation>une macro doit avoir un nom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro name {name!r}… is over {limit} characters</source>
        <translation>le nom de macro {name!r}… dépasse {limit} caractères</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro name {name!r} holds a control character</source>
        <translation>le nom de macro {name!r} contient un caractère de contrôle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name} is for {protocol}, not {device}</source>
        <translation>la macro {name} est pour {protocol}, pas pour {device}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name} has no steps</source>
        <translation>la macro {name} n&apos;a aucune étape</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name} has {count} steps; at most {limit}</source>
        <translation>la macro {name} a {count} étapes&#xa0;; {limit} au maximum</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name}, step {number} ({step!r}): {error}</source>
        <translation>macro {name}, étape {number} ({step!r})&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the step is over {limit} characters</source>
        <translation>l&apos;étape dépasse {limit} caractères</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a step is one line (use one step per line)</source>
        <translation>une étape tient sur une ligne (une étape par ligne)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the step is empty</source>
        <translation>l&apos;étape est vide</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown command {command!r}; a step is one of: {commands}</source>
        <translation>commande inconnue {command!r}&#xa0;; une étape est l&apos;une de&#xa0;: {commands}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command} is a {owner} command</source>
        <translation>{command} est une commande {owner}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>usage: wait SECONDS</source>
        <translation>usage&#xa0;: wait SECONDES</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wait {seconds:g} s refused: from 0 to {limit:g} s</source>
        <translation>wait {seconds:g} s refusé&#xa0;: de 0 à {limit:g} s</translation>
    </message>
    <message>
        <source>{name} stopped before step {number} ({step})</source>
        <translation type="vanished">{name}&#xa0;: arrêt avant l&apos;étape {number} ({step})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name} stopped before step {number} ({step})</source>
        <translation>macro {name}&#xa0;: arrêt avant l&apos;étape {number} ({step})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name} stopped during step {number}</source>
        <translation>macro {name}&#xa0;: arrêt pendant l&apos;étape {number}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: not a Motion Panel macro file (no &quot;format&quot;: &quot;{format}&quot;)</source>
        <translation>{where}&#xa0;: pas un fichier de macros Motion Panel (pas de &quot;format&quot;: &quot;{format}&quot;)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: macro file version {version!r}; this reads {reads}</source>
        <translation>{where}&#xa0;: fichier de macros en version {version!r}&#xa0;; cette version lit la {reads}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: &quot;macros&quot; is not a list</source>
        <translation>{where}&#xa0;: &quot;macros&quot; n&apos;est pas une liste</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {count} macros; at most {limit}</source>
        <translation>{where}&#xa0;: {count} macros&#xa0;; {limit} au maximum</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: macro {number}</source>
        <translation>{where}&#xa0;: macro {number}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: two {protocol} macros are named {name!r}</source>
        <translation>{where}&#xa0;: deux macros {protocol} sont nommées {name!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where} is not an object with name, protocol and steps</source>
        <translation>{where} n&apos;est pas un objet avec name, protocol et steps</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where} has no name</source>
        <translation>{where} n&apos;a pas de nom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where} ({name!r}): unknown protocol {protocol!r}</source>
        <translation>{where} ({name!r})&#xa0;: protocole inconnu {protocol!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where} ({name!r}): &quot;steps&quot; is not a list of strings</source>
        <translation>{where} ({name!r})&#xa0;: &quot;steps&quot; n&apos;est pas une liste de chaînes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where} ({name!r}): over {limit} steps or a step too long</source>
        <translation>{where} ({name!r})&#xa0;: plus de {limit} étapes ou une étape trop longue</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro file</source>
        <translation>fichier de macros</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{path}: not JSON ({error})</source>
        <translation>{path}&#xa0;: pas du JSON ({error})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} is not a JSON number</source>
        <translation>{name} n&apos;est pas un nombre JSON</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>saved macros</source>
        <translation>macros enregistrées</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>it cannot be read</source>
        <translation>il est illisible</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>it is not an INI file Qt can read</source>
        <translation>ce n&apos;est pas un fichier INI lisible par Qt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>settings file</source>
        <translation>fichier de réglages</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot read the settings file {file}: {why}</source>
        <translation>impossible de lire le fichier de réglages {file}&#xa0;: {why}</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>{url} ({protocol}, {baud} baud)</source>
        <translation>{url} ({protocol}, {baud} bauds)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{error}; waiting for {url}</source>
        <translation>{error}&#xa0;; en attente de {url}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the saved setup was refused: {error}</source>
        <translation>la configuration enregistrée a été refusée&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{identity} on {url}</source>
        <translation>{identity} sur {url}</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>{line} not changed: not connected</source>
        <translation>{line} inchangé&#xa0;: non connecté</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no break sent: not connected</source>
        <translation>aucun break envoyé&#xa0;: non connecté</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>the position went from ({position}) to (0, 0, 0) mm while nothing was sent: the device restarted</source>
        <translation>la position est passée de ({position}) à (0, 0, 0) mm sans que rien n&apos;ait été envoyé&#xa0;: l&apos;appareil a redémarré</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>{error}; not sent: {jobs}; talking to it again</source>
        <translation>{error}&#xa0;; non envoyé&#xa0;: {jobs}&#xa0;; reprise du dialogue avec l&apos;appareil</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>{error}; talking to it again</source>
        <translation>{error}&#xa0;; reprise du dialogue avec l&apos;appareil</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not sent: the device is being reconnected</source>
        <translation>non envoyé&#xa0;: reconnexion de l&apos;appareil en cours</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>stopped before it was sent</source>
        <translation>arrêté avant son envoi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the connection was lost</source>
        <translation>la connexion a été perdue</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>abandoned: disconnected while it was under way</source>
        <translation>abandonné&#xa0;: déconnexion en cours d&apos;exécution</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>relative move by ({dx:g}, {dy:g}, {dz:g}) {unit}</source>
        <translation>mouvement relatif de ({dx:g}, {dy:g}, {dz:g}) {unit}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown job {job!r}</source>
        <translation>tâche inconnue {job!r}</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>{hint} ({error})</source>
        <translation>{hint} ({error})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{error}; not sent: {jobs}</source>
        <translation>{error}&#xa0;; non envoyé&#xa0;: {jobs}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{error}; connecting again when {url} is back</source>
        <translation>{error}&#xa0;; reconnexion dès que {url} sera de nouveau disponible</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{url} is back: connecting again</source>
        <translation>{url} est de nouveau disponible&#xa0;: reconnexion</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device says: {text}</source>
        <translation>l&apos;appareil dit&#xa0;: {text}</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the bridge to {device} is closed</source>
        <translation>la passerelle vers {device} est fermée</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot create a pseudo-terminal for {device}: {error}</source>
        <translation>impossible de créer un pseudo-terminal pour {device}&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bridge is not open</source>
        <translation>la passerelle n&apos;est pas ouverte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device on {device} failed: {error}</source>
        <translation>l&apos;appareil sur {device} a échoué&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device on {device} went away: {error}</source>
        <translation>l&apos;appareil sur {device} a disparu&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device on {device} went away (its port was closed)</source>
        <translation>l&apos;appareil sur {device} a disparu (son port a été fermé)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the pseudo-terminal {path} failed: {error}</source>
        <translation>le pseudo-terminal {path} a échoué&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>writing to the device on {device} failed: {error}</source>
        <translation>échec de l&apos;écriture vers l&apos;appareil sur {device}&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>writing to the pseudo-terminal {path} failed: {error}</source>
        <translation>échec de l&apos;écriture vers le pseudo-terminal {path}&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>abandoned: the connection is closing</source>
        <translation>abandonné&#xa0;: la connexion se ferme</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{error}; still full after {seconds:.0f} s</source>
        <translation>{error}&#xa0;; toujours pleine après {seconds:.0f} s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command} failed after {tries} tries; the last: {error}</source>
        <translation>échec de {command} après {tries} tentatives&#xa0;; la dernière&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device restarted during {command} ({event}): its position and settings are lost</source>
        <translation>l&apos;appareil a redémarré pendant {command} ({event})&#xa0;: sa position et ses réglages sont perdus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device restarted ({event}): its position and settings are lost</source>
        <translation>l&apos;appareil a redémarré ({event})&#xa0;: sa position et ses réglages sont perdus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device did not finish its reply to {command} within {seconds:.3g} s</source>
        <translation>l&apos;appareil n&apos;a pas terminé sa réponse à {command} en {seconds:.3g} s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device did not answer to {command} within {seconds:.3g} s</source>
        <translation>l&apos;appareil n&apos;a pas répondu à {command} en {seconds:.3g} s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{message}; it sent {count} unexpected frame(s), the last: {frame}</source>
        <translation>{message}&#xa0;; il a envoyé {count} trame(s) inattendue(s), la dernière&#xa0;: {frame}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{message} (it may still be moving: {protocol} answers nothing until a blocking move has ended; try again once it has stopped)</source>
        <translation>{message} (il est peut-être encore en mouvement&#xa0;: {protocol} ne répond rien tant qu&apos;un mouvement bloquant n&apos;est pas terminé&#xa0;; réessayer une fois l&apos;appareil arrêté)</translation>
    </message>
    <message>
        <location line="+87"/>
        <source>no modem control lines</source>
        <translation>aucune ligne de contrôle modem</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{dtr}, {rts}, {cts}, {dsr}, {cd}, {ri}</source>
        <translation>{dtr}, {rts}, {cts}, {dsr}, {cd}, {ri}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{line} ?</source>
        <translation>{line}&#xa0;?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{line} on</source>
        <translation>{line} actif</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{line} off</source>
        <translation>{line} inactif</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>unreadable: {error}</source>
        <translation>illisible&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>error {code}: {message}</source>
        <translation>erreur {code}&#xa0;: {message}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error: {message}</source>
        <translation>erreur&#xa0;: {message}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position unknown (({x:g}, {y:g}, {z:g}) mm counted from where the session began; Home or Set Home to know it)</source>
        <translation>position inconnue (({x:g}, {y:g}, {z:g}) mm comptés depuis l&apos;endroit où la session a commencé&#xa0;; «&#xa0;Origine&#xa0;» ou «&#xa0;Définir l&apos;origine&#xa0;» pour la connaître)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position ({x:g}, {y:g}, {z:g}) mm</source>
        <translation>position ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position ({x:g}, {y:g}, {z:g}) mm (commanded, confirmed)</source>
        <translation>position ({x:g}, {y:g}, {z:g}) mm (commandée, confirmée)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position ({x:g}, {y:g}, {z:g}) mm (commanded)</source>
        <translation>position ({x:g}, {y:g}, {z:g}) mm (commandée)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>feedback {code} ({meaning})</source>
        <translation>retour {code} ({meaning})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>feedback {code} {bytes}</source>
        <translation>retour {code} {bytes}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>feedback {code}</source>
        <translation>retour {code}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the line {text!r}</source>
        <translation>la ligne {text!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an unreadable frame ({reason}): {bytes}</source>
        <translation>une trame illisible ({reason})&#xa0;: {bytes}</translation>
    </message>
    <message>
        <location line="-95"/>
        <source>a directory</source>
        <translation>un répertoire</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a named pipe (FIFO)</source>
        <translation>un tube nommé (FIFO)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a character device</source>
        <translation>un périphérique caractère</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a block device</source>
        <translation>un périphérique bloc</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a socket</source>
        <translation>un socket</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot read the {what} {file}: {why}</source>
        <translation>impossible de lire le {what} {file}&#xa0;: {why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{kind}, not a regular file</source>
        <translation>{kind}, pas un fichier ordinaire</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a special file</source>
        <translation>un fichier spécial</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: larger than {limit} ({size:,} bytes), too large for a {what}</source>
        <translation>{file}&#xa0;: plus de {limit} ({size:,} octets), trop grand pour un {what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: larger than {limit}, too large for a {what}</source>
        <translation>{file}&#xa0;: plus de {limit}, trop grand pour un {what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: not UTF-8 text (line {line}), not a {what}</source>
        <translation>{file}&#xa0;: pas du texte UTF-8 (ligne {line}), pas un {what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: a NUL byte (line {line}), not a {what}</source>
        <translation>{file}&#xa0;: un octet NUL (ligne {line}), pas un {what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file} line {line}: longer than {limit:,} characters, not a {what} line</source>
        <translation>{file} ligne {line}&#xa0;: plus de {limit:,} caractères, pas une ligne de {what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a frame body is {expected} bytes, not {length}</source>
        <translation>un corps de trame fait {expected} octets, pas {length}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>flag byte {byte:#04x}, expected 0xf0</source>
        <translation>octet de drapeau {byte:#04x}, 0xf0 attendu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>checksum {got:#04x}, expected {expected:#04x}</source>
        <translation>somme de contrôle {got:#04x}, {expected:#04x} attendu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0x90 followed by {byte:#04x} inside the data</source>
        <translation>0x90 suivi de {byte:#04x} dans les données</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no tail within {most} bytes</source>
        <translation>pas de fin de trame en {most} octets</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a SysEx message needs at least a command byte</source>
        <translation>un message SysEx nécessite au moins un octet de commande</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SysEx data must be 7-bit; got {byte:#04x}</source>
        <translation>les données SysEx doivent être sur 7 bits&#xa0;; reçu {byte:#04x}</translation>
    </message>
    <message>
        <location line="+356"/>
        <source>{source} names no protocol: decoded as {protocol}, which its traffic reads as ({frames} frames recognised)</source>
        <translation>{source} n&apos;indique aucun protocole&#xa0;: décodé en {protocol}, le protocole que révèle son trafic ({frames} trames reconnues)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {number}: not a traffic log line: {line!r}</source>
        <translation>{source} ligne {number}&#xa0;: pas une ligne de journal de trafic&#xa0;: {line!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no traffic in it (not a Motion Panel log)</source>
        <translation>{source}&#xa0;: aucun trafic (pas un journal Motion Panel)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>traffic log</source>
        <translation>journal de trafic</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: not a Motion Panel log nor a pyserial spy:// capture: line {number} is not a traffic log line: {line!r}; for spy://, {hint}</source>
        <translation>{file}&#xa0;: ni un journal Motion Panel ni une capture pyserial spy://&#xa0;: la ligne {number} n&apos;est pas une ligne de journal de trafic&#xa0;: {line!r}&#xa0;; pour spy://, {hint}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: empty, not a Motion Panel log nor a pyserial spy:// capture (spy&apos;s raw format leaves its file empty); {hint}</source>
        <translation>{file}&#xa0;: vide, ni un journal Motion Panel ni une capture pyserial spy:// (le format raw de spy laisse son fichier vide)&#xa0;; {hint}</translation>
    </message>
    <message>
        <location line="-446"/>
        <source>the device reported: {reported}</source>
        <translation>l&apos;appareil a signalé&#xa0;: {reported}</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>{protocol} device</source>
        <translation>appareil {protocol}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device did not report a position (it answered {value})</source>
        <translation>l&apos;appareil n&apos;a pas indiqué de position (il a répondu {value})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device is at ({x:g}, {y:g}, {z:g}) mm, not where its last move ended: its replies are no longer taken as arrival</source>
        <translation>l&apos;appareil est à ({x:g}, {y:g}, {z:g}) mm, et non là où son dernier mouvement s&apos;est terminé&#xa0;: ses réponses ne valent plus confirmation d&apos;arrivée</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>{protocol} has no speed limits to report</source>
        <translation>{protocol} n&apos;a pas de limites de vitesse à indiquer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed {speed:g} refused: the speed must be a positive number</source>
        <translation>vitesse {speed:g} refusée&#xa0;: la vitesse doit être un nombre positif</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed {speed:g} {unit} refused: the device allows {low:g} to {high:g} {unit}</source>
        <translation>vitesse {speed:g} {unit} refusée&#xa0;: l&apos;appareil accepte de {low:g} à {high:g} {unit}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed {speed:g} {unit} written, but this firmware times its steps from its step delays (15, 16) alone: moves go at {real:.3f} {unit}</source>
        <translation>vitesse {speed:g} {unit} écrite, mais ce firmware cadence ses pas uniquement sur ses délais entre pas (15, 16)&#xa0;: les mouvements se font à {real:.3f} {unit}</translation>
    </message>
    <message>
        <location line="-36"/>
        <source>move to ({x:g}, {y:g}, {z:g}) mm</source>
        <translation>déplacement vers ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>jog by ({dx:g}, {dy:g}, {dz:g}) {unit}</source>
        <translation>déplacement relatif de ({dx:g}, {dy:g}, {dz:g}) {unit}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no way to go home</source>
        <translation>{protocol} n&apos;a aucun moyen de retourner à l&apos;origine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>go home</source>
        <translation>retour à l&apos;origine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no set-home command</source>
        <translation>{protocol} n&apos;a pas de commande pour définir l&apos;origine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what} refused: home is outside the travel limits</source>
        <translation>{what} refusé&#xa0;: l&apos;origine est hors des limites de course</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no arc moves</source>
        <translation>{protocol} n&apos;a pas de mouvements en arc</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>arc</source>
        <translation>arc</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no dwell</source>
        <translation>{protocol} n&apos;a pas de temporisation</translation>
    </message>
    <message>
        <location line="-19"/>
        <source>stopped at ({x:g}, {y:g}, {z:g}) mm</source>
        <translation>arrêté à ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the move to {target} did not end within {seconds:.1f} s</source>
        <translation>le déplacement vers {target} ne s&apos;est pas terminé en {seconds:.1f} s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no protocol to read them with</source>
        <translation>aucun protocole pour les lire</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>program point {number}</source>
        <translation>point {number} du programme</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw bytes refused: {protocol} cannot read them as a command ({reason}), so they cannot be checked against the travel limits ({box}); send them with force to send them anyway</source>
        <translation>octets bruts refusés&#xa0;: {protocol} ne peut pas les lire comme une commande ({reason}), ils ne peuvent donc pas être vérifiés par rapport aux limites de course ({box})&#xa0;; forcer l&apos;envoi pour les envoyer quand même</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw bytes refused: they hold {count} commands, {moves} of them moves; send a move alone, so that it is checked and followed to its end</source>
        <translation>octets bruts refusés&#xa0;: ils contiennent {count} commandes, dont {moves} déplacements&#xa0;; envoyer un déplacement seul, pour qu&apos;il soit vérifié et suivi jusqu&apos;à sa fin</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw move {command}</source>
        <translation>déplacement brut {command}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what}: not a move the panel can check</source>
        <translation>{what}&#xa0;: pas un déplacement que le panneau sait vérifier</translation>
    </message>
    <message>
        <location line="+214"/>
        <source>{what} {text!r} is not a number the device accepts: use digits with an optional sign and one decimal point, e.g. -12.5</source>
        <translation>{what} {text!r} n&apos;est pas un nombre accepté par l&apos;appareil&#xa0;: utiliser des chiffres, avec un signe facultatif et un seul point décimal, par ex. -12.5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what} {value!r} is not a finite number</source>
        <translation>{what} {value!r} n&apos;est pas un nombre fini</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what} {value:g} is out of range: the device handles at most ±{limit:g}</source>
        <translation>{what} {value:g} est hors plage&#xa0;: l&apos;appareil accepte au plus ±{limit:g}</translation>
    </message>
    <message>
        <location line="-203"/>
        <source>{source}: not a parameter profile: {error}</source>
        <translation>{source}&#xa0;: pas un profil de paramètres&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: not a parameter profile: a number too long</source>
        <translation>{source}&#xa0;: pas un profil de paramètres&#xa0;: nombre trop long</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: not a parameter profile: nested too deeply</source>
        <translation>{source}&#xa0;: pas un profil de paramètres&#xa0;: imbrication trop profonde</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: protocol must be a name in quotes</source>
        <translation>{source}&#xa0;: protocol doit être un nom entre guillemets</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: a profile for {named!r}, not for {protocol!r}</source>
        <translation>{source}&#xa0;: profil pour {named!r}, pas pour {protocol!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} (line {line}): unknown key {key!r}</source>
        <translation>{source} (ligne {line})&#xa0;: clé inconnue {key!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: unknown key {key!r}</source>
        <translation>{source}&#xa0;: clé inconnue {key!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no [parameters] table with values in it</source>
        <translation>{source}&#xa0;: aucune table [parameters] contenant des valeurs</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {line}</source>
        <translation>{source} ligne {line}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: unknown parameter {name!r} for {protocol}</source>
        <translation>{where}&#xa0;: paramètre inconnu {name!r} pour {protocol}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {error}</source>
        <translation>{where}&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {name}: not a number the device takes ({range})</source>
        <translation>{where}&#xa0;: {name}&#xa0;: pas un nombre accepté par l&apos;appareil ({range})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: only firmware outputs ({names}), which a profile does not write</source>
        <translation>{source}&#xa0;: uniquement des sorties du firmware ({names}), qu&apos;un profil n&apos;écrit pas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>profile</source>
        <translation>profil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot write the profile {path}: {error}</source>
        <translation>impossible d&apos;écrire le profil {path}&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+190"/>
        <source>{low} to {high} in steps of {step}</source>
        <translation>de {low} à {high} par pas de {step}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{low} to {high} (whole numbers)</source>
        <translation>de {low} à {high} (nombres entiers)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{low} to {high}</source>
        <translation>de {low} à {high}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: {value!r} is not a number ({range})</source>
        <translation>{name}&#xa0;: {value!r} n&apos;est pas un nombre ({range})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: {value} refused: {range}</source>
        <translation>{name}&#xa0;: {value} refusé&#xa0;: {range}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: {value} refused: the device takes {range}</source>
        <translation>{name}&#xa0;: {value} refusé&#xa0;: l&apos;appareil accepte {range}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>this protocol has no parameters</source>
        <translation>ce protocole n&apos;a pas de paramètres</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown parameter {name!r} (did you mean {close}?): use a name or an id 1..{count}; &apos;motionctl ... param list&apos; lists them</source>
        <translation>paramètre inconnu {name!r} (vouliez-vous dire {close}&#xa0;?)&#xa0;: utiliser un nom ou un id 1..{count}&#xa0;; &apos;motionctl ... param list&apos; les liste</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown parameter {name!r}: use a name or an id 1..{count}; &apos;motionctl ... param list&apos; lists them</source>
        <translation>paramètre inconnu {name!r}&#xa0;: utiliser un nom ou un id 1..{count}&#xa0;; &apos;motionctl ... param list&apos; les liste</translation>
    </message>
    <message>
        <location line="-197"/>
        <source>its frames carry absolute targets, so a relative move needs the position: Set Home where the stage stands, Home, or move to an absolute point first (in the panel, or motionctl set-home, home or move X Y Z)</source>
        <translation>ses trames portent des cibles absolues, un mouvement relatif a donc besoin de la position&#xa0;: d&apos;abord «&#xa0;Définir l&apos;origine&#xa0;» là où se trouve la platine, «&#xa0;Origine&#xa0;», ou un mouvement vers un point absolu (dans le panneau, ou motionctl set-home, home ou move X Y Z)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Home or Set Home (in the panel, or motionctl home / set-home) to start counting</source>
        <translation>«&#xa0;Origine&#xa0;» ou «&#xa0;Définir l&apos;origine&#xa0;» (dans le panneau, ou motionctl home / set-home) pour commencer le décompte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Set Home where the stage stands (in the panel, or motionctl set-home) to start counting; with no home move of its own, Home needs a count too</source>
        <translation>«&#xa0;Définir l&apos;origine&#xa0;» là où se trouve la platine (dans le panneau, ou motionctl set-home) pour commencer le décompte&#xa0;; faute de mouvement de prise d&apos;origine propre, «&#xa0;Origine&#xa0;» a lui aussi besoin d&apos;un décompte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command} refused: position unknown: {protocol} cannot be asked where it is and no commanded position is kept for this port; {how}</source>
        <translation>{command} refusé&#xa0;: position inconnue&#xa0;: {protocol} ne peut pas être interrogé sur sa position et aucune position commandée n&apos;est conservée pour ce port&#xa0;; {how}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command} refused: position unknown: {protocol} cannot be asked where it is and no position is counted for this port; {how}</source>
        <translation>{command} refusé&#xa0;: position inconnue&#xa0;: {protocol} ne peut pas être interrogé sur sa position et aucune position n&apos;est comptée pour ce port&#xa0;; {how}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position unknown: {protocol} cannot be asked where it is and no commanded position is kept for this port; {how}</source>
        <translation>position inconnue&#xa0;: {protocol} ne peut pas être interrogé sur sa position et aucune position commandée n&apos;est conservée pour ce port&#xa0;; {how}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position unknown: {protocol} cannot be asked where it is and no position is counted for this port; {how}</source>
        <translation>position inconnue&#xa0;: {protocol} ne peut pas être interrogé sur sa position et aucune position n&apos;est comptée pour ce port&#xa0;; {how}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>this firmware reads the digits as µm whatever the type letter ({kind} is not read): the stage moves X {x:.3f} mm, Y {y:.3f} mm</source>
        <translation>ce firmware lit les chiffres comme des µm quelle que soit la lettre de type ({kind} n&apos;est pas lu)&#xa0;: la platine se déplace de X {x:.3f} mm, Y {y:.3f} mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no identity query: the device cannot be asked what it is</source>
        <translation>{protocol} n&apos;a pas de requête d&apos;identification&#xa0;: l&apos;appareil ne peut pas être interrogé sur ce qu&apos;il est</translation>
    </message>
    <message>
        <location line="+367"/>
        <source>{where}: {name} {value!r} is not a number</source>
        <translation>{where}&#xa0;: {name} {value!r} n&apos;est pas un nombre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {name} is not a finite float32 number</source>
        <translation>{where}&#xa0;: {name} n&apos;est pas un nombre float32 fini</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>{where}: {name} {value!r} is not a finite float32 number</source>
        <translation>{where}&#xa0;: {name} {value!r} n&apos;est pas un nombre float32 fini</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>{where}: speed {speed:g} mm/s must be above 0</source>
        <translation>{where}&#xa0;: la vitesse {speed:g} mm/s doit être supérieure à 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {line}: not CSV: {error}</source>
        <translation>{source} ligne {line}&#xa0;: pas du CSV&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {line}: the header must name x, y, z and speed (got nothing)</source>
        <translation>{source} ligne {line}&#xa0;: l&apos;en-tête doit nommer x, y, z et speed (en-tête vide)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {line}: the header must name x, y, z and speed (got {columns})</source>
        <translation>{source} ligne {line}&#xa0;: l&apos;en-tête doit nommer x, y, z et speed (trouvé&#xa0;: {columns})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {line}: {count} values, expected 4</source>
        <translation>{source} ligne {line}&#xa0;: {count} valeurs, 4 attendues</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no header line (x,y,z,speed)</source>
        <translation>{source}&#xa0;: pas de ligne d&apos;en-tête (x,y,z,speed)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no points</source>
        <translation>{source}&#xa0;: aucun point</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {line}: not JSON ({reason})</source>
        <translation>{source} ligne {line}&#xa0;: pas du JSON ({reason})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: not JSON the panel reads (a number too long)</source>
        <translation>{source}&#xa0;: JSON illisible par le panneau (nombre trop long)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: not JSON the panel reads (nested too deeply)</source>
        <translation>{source}&#xa0;: JSON illisible par le panneau (imbrication trop profonde)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no &quot;points&quot; list</source>
        <translation>{source}&#xa0;: pas de liste &quot;points&quot;</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: expected [x, y, z, speed]</source>
        <translation>{where}&#xa0;: [x, y, z, speed] attendu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} point {number}</source>
        <translation>{source} point {number}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: more than {count} points</source>
        <translation>{source}&#xa0;: plus de {count} points</translation>
    </message>
    <message>
        <location line="-45"/>
        <source>program</source>
        <translation>programme</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>cannot write the program {path}: {error}</source>
        <translation>impossible d&apos;écrire le programme {path}&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="-173"/>
        <source>this looks like a {found} controller, not {expected}</source>
        <translation>cela ressemble à un contrôleur {found}, pas {expected}</translation>
    </message>
    <message>
        <location line="-369"/>
        <source>--device names a device of a bench: give --bench FILE</source>
        <translation>--device désigne un appareil d&apos;un banc&#xa0;: donnez --bench FICHIER</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>--port and --bench both name the device: give one of them</source>
        <translation>--port et --bench désignent tous deux l&apos;appareil&#xa0;: n&apos;en donnez qu&apos;un</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{bench} has {count} devices: choose one with --device ({names})</source>
        <translation>{bench} a {count} appareils&#xa0;: choisissez-en un avec --device ({names})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{bench} has no device {name!r} (it has {names})</source>
        <translation>{bench} n&apos;a pas d&apos;appareil {name!r} (il a {names})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>--protocol {typed} disagrees with the bench: {name} is {protocol}</source>
        <translation>--protocol {typed} contredit le banc&#xa0;: {name} est {protocol}</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>{what} {text!r} refused: a whole number is needed</source>
        <translation>{what} {text!r} refusé : un nombre entier est nécessaire</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>radius {radius:g} mm refused: it must be above 0</source>
        <translation>rayon de {radius:g} mm refusé : il doit être supérieur à 0</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;{command}&apos; is a {owner} command, not {protocol}&apos;s</source>
        <translation>« {command} » est une commande de {owner}, pas de {protocol}</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>{axis} {value:g} mm refused: outside {low:g}..{high:g} mm (travel limits)</source>
        <translation>{axis} {value:g} mm refusé&#xa0;: hors de {low:g}..{high:g} mm (limites de course)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the stage is not connected: connect it first</source>
        <translation>la platine n&apos;est pas connectée&#xa0;: connectez-la d&apos;abord</translation>
    </message>
    <message>
        <location line="+136"/>
        <source>{setting} {value} refused: {minimum:g} to {maximum:g} {unit}</source>
        <translation>{setting} {value} refusé&#xa0;: de {minimum:g} à {maximum:g} {unit}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no setting {name!r}</source>
        <translation>{protocol} n&apos;a pas de réglage {name!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no wire variants (got {name!r})</source>
        <translation>{protocol} n&apos;a pas de variante de ligne (demandée&#xa0;: {name!r})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no variant {name!r} (variants: {known})</source>
        <translation>{protocol} n&apos;a pas de variante {name!r} (variantes&#xa0;: {known})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} moves are linear only (got {kind!r})</source>
        <translation>les mouvements {protocol} sont uniquement linéaires (reçu {kind!r})</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>{protocol} cannot read sent frames</source>
        <translation>{protocol} ne sait pas lire les trames envoyées</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the last {count} bytes are not a whole frame: the device would wait for the rest</source>
        <translation>les {count} derniers octets ne forment pas une trame complète&#xa0;: l&apos;appareil attendrait la suite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no whole frame in {count} bytes</source>
        <translation>aucune trame complète dans {count} octets</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} coordinate</source>
        <translation>coordonnée {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} distance</source>
        <translation>distance {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed</source>
        <translation>vitesse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a coordinate</source>
        <translation>une coordonnée</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the speed</source>
        <translation>la vitesse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed {speed:g} mm/s refused: the speed must be positive</source>
        <translation>vitesse {speed:g} mm/s refusée&#xa0;: la vitesse doit être positive</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw command refused: COXIRIS takes ASCII text only</source>
        <translation>commande brute refusée&#xa0;: COXIRIS n&apos;accepte que du texte ASCII</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw command refused: one line at a time (it contains a line break)</source>
        <translation>commande brute refusée&#xa0;: une ligne à la fois (elle contient un saut de ligne)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw command refused: it is empty, and the device ignores blank lines</source>
        <translation>commande brute refusée&#xa0;: elle est vide, et l&apos;appareil ignore les lignes vides</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>COXIRIS has no command for {command}</source>
        <translation>COXIRIS n&apos;a pas de commande pour {command}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>command refused: {length} characters, the device takes at most {most} ({start}...)</source>
        <translation>commande refusée&#xa0;: {length} caractères, l&apos;appareil en accepte au plus {most} ({start}...)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device reported {what} as {text!r}, which is not a number</source>
        <translation>l&apos;appareil a renvoyé {text!r} pour {what}, ce qui n&apos;est pas un nombre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device reported {what} as {text!r}</source>
        <translation>l&apos;appareil a renvoyé {text!r} pour {what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device does not know the command {name!r}</source>
        <translation>l&apos;appareil ne connaît pas la commande {name!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device refused the command: {error}</source>
        <translation>l&apos;appareil a refusé la commande&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>expected DONE {command}, got {event}</source>
        <translation>DONE {command} attendu, reçu {event}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position reply {data!r} does not hold three numbers</source>
        <translation>la réponse de position {data!r} ne contient pas trois nombres</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speeds are reported rounded to whole mm/s</source>
        <translation>les vitesses sont indiquées arrondies au mm/s entier</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>positions are reported to 0.01 mm</source>
        <translation>les positions sont indiquées à 0.01 mm près</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>non-ASCII bytes in a COXIRIS line: {bytes}</source>
        <translation>octets non ASCII dans une ligne COXIRIS&#xa0;: {bytes}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>line refused: {length} characters, the device takes at most {most}</source>
        <translation>ligne refusée&#xa0;: {length} caractères, l&apos;appareil en accepte au plus {most}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{line!r} has no line end: the device would wait for the rest</source>
        <translation>{line!r} n&apos;a pas de fin de ligne&#xa0;: l&apos;appareil attendrait la suite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an empty line: the device ignores it</source>
        <translation>une ligne vide&#xa0;: l&apos;appareil l&apos;ignore</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>non-ASCII bytes: COXIRIS takes ASCII text only</source>
        <translation>octets non ASCII&#xa0;: COXIRIS n&apos;accepte que du texte ASCII</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} {params!r} is not three numbers as the firmware reads them</source>
        <translation>{name} {params!r} ne donne pas trois nombres tels que le firmware les lit</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Motor steps per turn</source>
        <translation>Pas moteur par tour</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Motor steps per millimetre</source>
        <translation>Pas moteur par millimètre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Motor control pin {pin} (-1: none)</source>
        <translation>Broche de commande moteur {pin} (-1&#xa0;: aucune)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moves back to 0 by a relative move: the board has no homing</source>
        <translation>Revient à 0 par un mouvement relatif&#xa0;: la carte n&apos;a pas de prise d&apos;origine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no completion message: moves are estimated from speed and steps</source>
        <translation>pas de message de fin&#xa0;: les mouvements sont estimés d&apos;après la vitesse et le nombre de pas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the version and firmware name (is a Firmata board on this port?)</source>
        <translation>la demande de version et de nom du firmware (une carte Firmata est-elle sur ce port&#xa0;?)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed (rpm)</source>
        <translation>vitesse (rpm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>steps per revolution</source>
        <translation>pas par tour</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pin</source>
        <translation>broche</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>steps</source>
        <translation>pas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>capability response</source>
        <translation>réponse des capacités</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>analog mapping</source>
        <translation>correspondance analogique</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>version request</source>
        <translation>demande de version</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>firmware name request</source>
        <translation>demande du nom du firmware</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>STEPPER_LIBRARY_VERSION request</source>
        <translation>demande STEPPER_LIBRARY_VERSION</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what} {value} refused: the stepper takes {low} to {high}</source>
        <translation>{what}&#xa0;: {value} refusé, le moteur pas à pas accepte de {low} à {high}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the board answered: {error}</source>
        <translation>la carte a répondu&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{distance:g} mm refused: the motor moves in steps of {step:g} mm ({per_mm:g} steps/mm)</source>
        <translation>{distance:g} mm refusé&#xa0;: le moteur se déplace par pas de {step:g} mm ({per_mm:g} pas/mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the Firmata stepper is one axis (X): Y and Z must be 0</source>
        <translation>le moteur pas à pas Firmata n&apos;a qu&apos;un axe (X)&#xa0;: Y et Z doivent valoir 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{count} pins refused: a stepper has 2 or 4 pins</source>
        <translation>{count} broches refusées&#xa0;: un moteur pas à pas a 2 ou 4 broches</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmata has no message for {command}</source>
        <translation>Firmata n&apos;a pas de message pour {command}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an empty Firmata message</source>
        <translation>un message Firmata vide</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmata protocol {major}.{minor}</source>
        <translation>protocole Firmata {major}.{minor}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>analog pin {pin}: {value}</source>
        <translation>broche analogique {pin}&#xa0;: {value}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>digital port {port}: {bits:08b}</source>
        <translation>port numérique {port}&#xa0;: {bits:08b}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>message {bytes}</source>
        <translation>message {bytes}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SysEx {command:#04x}</source>
        <translation>SysEx {command:#04x}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>STEPPER_CONFIGURE {steps} steps/rev, pins {pins}</source>
        <translation>STEPPER_CONFIGURE {steps} pas/tour, broches {pins}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>STEPPER_STEP {rpm} rpm, {steps} steps forward</source>
        <translation>STEPPER_STEP {rpm} rpm, {steps} pas en avant</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>STEPPER_STEP {rpm} rpm, {steps} steps reverse</source>
        <translation>STEPPER_STEP {rpm} rpm, {steps} pas en arrière</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a STEPPER_STEP of {count} data bytes, not 6</source>
        <translation>un STEPPER_STEP de {count} octets de données, au lieu de 6</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>framing</source>
        <translation>trame</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>checksum</source>
        <translation>somme de contrôle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown command</source>
        <translation>commande inconnue</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bad arguments</source>
        <translation>arguments invalides</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>queue full</source>
        <translation>file pleine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>undocumented</source>
        <translation>non documenté</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error {code} ({meaning}) for {command}</source>
        <translation>erreur {code} ({meaning}) pour {command}</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>speed {speed:g} mm/s refused: it must be above 0</source>
        <translation>vitesse {speed:g} mm/s refusée&#xa0;: elle doit être supérieure à 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the position reply holds {count} numbers, not 3</source>
        <translation>la réponse de position contient {count} nombres, et non 3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the status reply holds {count} numbers, not 2</source>
        <translation>la réponse d&apos;état contient {count} nombres, et non 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>undocumented code {code}</source>
        <translation>code {code} non documenté</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command}: the device answered error {code} ({meaning})</source>
        <translation>{command}&#xa0;: l&apos;appareil a répondu par l&apos;erreur {code} ({meaning})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>moves are queued on the device; the position is read back while they run</source>
        <translation>les mouvements sont mis en file sur l&apos;appareil&#xa0;; la position est relue pendant leur exécution</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The next queued frame&apos;s number (0: random)</source>
        <translation>Numéro de la prochaine trame en file (0&#xa0;: aléatoire)</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>dwell {ms} ms refused: the field is an int16 (0 to 32767)</source>
        <translation>temporisation de {ms} ms refusée&#xa0;: le champ est un int16 (0 à 32767)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a queued frame holds 1 to {most} queued instructions</source>
        <translation>une trame en file contient de 1 à {most} instructions en file</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the laser link has no instruction for {command}</source>
        <translation>la liaison laser n&apos;a pas d&apos;instruction pour {command}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MOVE_LINEAR with {count} float values, not x, y, z and speed</source>
        <translation>MOVE_LINEAR avec {count} valeurs flottantes, au lieu de x, y, z et la vitesse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>word {word:#04x}</source>
        <translation>mot {word:#04x}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>frame {number} ({words} ×{count})</source>
        <translation>trame {number} ({words} ×{count})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>frame {number} ({words})</source>
        <translation>trame {number} ({words})</translation>
    </message>
    <message>
        <location line="-28"/>
        <source>a field holds 1 to 255 values, not {count}</source>
        <translation>un champ contient de 1 à 255 valeurs, et non {count}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{value!r} is not one ASCII character</source>
        <translation>{value!r} n&apos;est pas un caractère ASCII unique</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{value} does not fit a float32</source>
        <translation>{value} ne tient pas dans un float32</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{value} does not fit a {kind} ({low} to {high})</source>
        <translation>{value} ne tient pas dans un {kind} ({low} à {high})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>command word {word:#04x} is outside 0x01..0x7F</source>
        <translation>le mot de commande {word:#04x} est hors de 0x01..0x7F</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>byte {index}: {byte:#04x} where a command word was expected</source>
        <translation>octet {index}&#xa0;: {byte:#04x} là où un mot de commande était attendu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>byte {index}: a {kind} field without its count</source>
        <translation>octet {index}&#xa0;: un champ {kind} sans son nombre de valeurs</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>byte {index}: {count} {kind} values run past the data</source>
        <translation>octet {index}&#xa0;: {count} valeurs {kind} dépassent la fin des données</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Encoder ticks per millimetre</source>
        <translation>Impulsions codeur par millimètre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moves back to (0, 0, 0) with a Linear frame: the device has no homing</source>
        <translation>Revient à (0, 0, 0) par une trame Linear&#xa0;: l&apos;appareil n&apos;a pas de prise d&apos;origine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write-only: positions are commanded, completion estimated from distance and speed</source>
        <translation>écriture seule&#xa0;: les positions sont des consignes, la fin est estimée d&apos;après la distance et la vitesse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed {axis}</source>
        <translation>vitesse {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>centre {axis}</source>
        <translation>centre {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>radius</source>
        <translation>rayon</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>angular speed</source>
        <translation>vitesse angulaire</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dwell</source>
        <translation>temporisation</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{field} {value:g} {unit} refused: a pi-frame field holds {low} to {high}</source>
        <translation>{field}&#xa0;: {value:g} {unit} refusé, un champ pi-frame accepte de {low} à {high}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{field} {distance:g} mm refused: the device moves in ticks of {tick:g} mm ({per_mm:g} ticks/mm)</source>
        <translation>{field}&#xa0;: {distance:g} mm refusé, l&apos;appareil se déplace par impulsions de {tick:g} mm ({per_mm:g} impulsions/mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{field} {distance:g} mm refused: {ticks} ticks do not fit 16 bits ({low:g} to {high:g} mm at {per_mm:g} ticks/mm)</source>
        <translation>{field}&#xa0;: {distance:g} mm refusé, {ticks} impulsions ne tiennent pas sur 16 bits ({low:g} à {high:g} mm à {per_mm:g} impulsions/mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pi-frame has no frame for {command}</source>
        <translation>pi-frame n&apos;a pas de trame pour {command}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a {length}-byte frame</source>
        <translation>une trame de {length} octets</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Linear X={x} Y={y} Z={z} ticks at {sx}/{sy}/{sz} ticks/s</source>
        <translation>Linear X={x} Y={y} Z={z} impulsions à {sx}/{sy}/{sz} impulsions/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Circular centre ({x}, {y}) radius {radius} ticks, {start:g}° to {end:g}° {turn} at {speed:g}°/s, Z to {z}</source>
        <translation>Circular centre ({x}, {y}) rayon {radius} impulsions, de {start:g}° à {end:g}° {turn} à {speed:g}°/s, Z vers {z}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dwell {ms} ms</source>
        <translation>Dwell {ms} ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>action {number}</source>
        <translation>action {number}</translation>
    </message>
    <message>
        <location line="+81"/>
        <source>move package confirmed</source>
        <translation>paquet de mouvement confirmé</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>action accomplished</source>
        <translation>action accomplie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>package size mismatch</source>
        <translation>taille de paquet incorrecte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid command type</source>
        <translation>type de commande invalide</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid motion type</source>
        <translation>type de mouvement invalide</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid direction for the X axis</source>
        <translation>sens invalide pour l&apos;axe X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid direction for the Y axis</source>
        <translation>sens invalide pour l&apos;axe Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid set parameter ID</source>
        <translation>ID de paramètre à écrire invalide</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>parse function error in the firmware</source>
        <translation>erreur de la fonction d&apos;analyse du firmware</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid driving mechanism</source>
        <translation>mécanisme d&apos;entraînement invalide</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an error code the documentation does not list</source>
        <translation>un code d&apos;erreur absent de la documentation</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{parameter} set</source>
        <translation>{parameter} écrit</translation>
    </message>
    <message>
        <source>Sets input_speed_steady_x and _y (parameters 21 and 22). This firmware revision times its steps from step_delay_instantaneous (15, 16) only, so moves keep their pace.</source>
        <translation type="vanished">Écrit input_speed_steady_x et _y (paramètres 21 et 22). Cette révision du firmware cadence ses pas uniquement sur step_delay_instantaneous (15, 16)&#xa0;: les mouvements gardent donc leur allure.</translation>
    </message>
    <message>
        <location line="-45"/>
        <source>Visiomex has no homing at this revision: Home moves back to (0, 0) by a relative move from the position the panel counted</source>
        <translation>Visiomex n&apos;a pas de prise d&apos;origine dans cette révision&#xa0;: «&#xa0;Origine&#xa0;» revient à (0, 0) par un mouvement relatif depuis la position comptée par le panneau</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no read-back: the panel keeps what was last written</source>
        <translation>pas de relecture&#xa0;: le panneau conserve la dernière valeur écrite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>positions are commanded, and confirmed by FA0001 when the move ends</source>
        <translation>les positions sont des consignes, confirmées par FA0001 à la fin du mouvement</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a reply comes 1 s after a packet: the firmware waits for 1 s of silence</source>
        <translation>une réponse arrive 1 s après un paquet&#xa0;: le firmware attend 1 s de silence</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>parameter {number} set</source>
        <translation>paramètre {number} écrit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>feedback code {code} is not documented</source>
        <translation>le code de retour {code} n&apos;est pas documenté</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command}: the device answered {code} ({meaning}); this firmware revision runs the move anyway</source>
        <translation>{command}&#xa0;: l&apos;appareil a répondu {code} ({meaning})&#xa0;; cette révision du firmware exécute quand même le mouvement</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command}: the device answered {code} ({meaning})</source>
        <translation>{command}&#xa0;: l&apos;appareil a répondu {code} ({meaning})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command}: expected {wanted}, got {code}</source>
        <translation>{command}&#xa0;: {wanted} attendu, reçu {code}</translation>
    </message>
    <message>
        <location line="-46"/>
        <source>18-character packets at 9600 baud, as the seed documents</source>
        <translation>paquets de 18 caractères à 9600 bauds, comme documenté dans le seed</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the seed&apos;s packets; feedback lines start with &apos;&gt;&apos;</source>
        <translation>les paquets du seed&#xa0;; les lignes de retour commencent par &apos;&gt;&apos;</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>12-character packets at 115200 baud, moves in mm, D goes home</source>
        <translation>paquets de 12 caractères à 115200 bauds, mouvements en mm, D ramène à l&apos;origine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Visiomex moves are relative: the panel sends the distance to go</source>
        <translation>les mouvements Visiomex sont relatifs&#xa0;: le panneau envoie la distance à parcourir</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the speed is parameters 21 and 22: it is sent as two sets</source>
        <translation>la vitesse correspond aux paramètres 21 et 22&#xa0;: elle est envoyée en deux écritures</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Visiomex has no packet for {command}</source>
        <translation>Visiomex n&apos;a pas de paquet pour {command}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>move kind {kind!r} refused: Visiomex moves are {kinds}</source>
        <translation>type de mouvement {kind!r} refusé&#xa0;: les mouvements Visiomex sont {kinds}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z {distance:g} mm refused: the Visiomex controller has X and Y only</source>
        <translation>Z {distance:g} mm refusé&#xa0;: le contrôleur Visiomex n&apos;a que X et Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} {value:g} {unit} refused: this device moves in 1 µm</source>
        <translation>{axis} {value:g} {unit} refusé&#xa0;: cet appareil se déplace par incréments de 1 µm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} {value:g} {unit} refused: this device moves in whole {unit}</source>
        <translation>{axis} {value:g} {unit} refusé&#xa0;: cet appareil se déplace par {unit} entiers</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} {value:g} {unit} refused: one move goes at most {most} {unit} per axis ({digits} digits)</source>
        <translation>{axis} {value:g} {unit} refusé&#xa0;: un mouvement va au plus à {most} {unit} par axe ({digits} chiffres)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>packet refused: Visiomex takes ASCII characters only</source>
        <translation>paquet refusé&#xa0;: Visiomex n&apos;accepte que des caractères ASCII</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>packet refused: it is empty</source>
        <translation>paquet refusé&#xa0;: il est vide</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>packet refused: {length} characters, a Visiomex packet has {most} (a line ending counts too)</source>
        <translation>paquet refusé&#xa0;: {length} caractères, un paquet Visiomex en a {most} (une fin de ligne compte aussi)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>non-ASCII bytes in a Visiomex line: {bytes}</source>
        <translation>octets non ASCII dans une ligne Visiomex&#xa0;: {bytes}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>that packet gets no reply: send it from the console instead</source>
        <translation>ce paquet ne reçoit pas de réponse&#xa0;: l&apos;envoyer plutôt depuis la console</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>packet {packet}</source>
        <translation>paquet {packet}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set {parameter} = {value}</source>
        <translation>écriture {parameter} = {value}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>move linear X {x} Y {y}</source>
        <translation>mouvement linéaire X {x} Y {y}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>move rotational X {x} Y {y}</source>
        <translation>mouvement rotatif X {x} Y {y}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>move steps X {x} Y {y}</source>
        <translation>mouvement en pas X {x} Y {y}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>move {kind} X {x} Y {y}</source>
        <translation>mouvement {kind} X {x} Y {y}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>packet {packet!r}</source>
        <translation>paquet {packet!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>move packet {packet!r} is not as the protocol documents</source>
        <translation>le paquet de mouvement {packet!r} n&apos;est pas conforme à la documentation du protocole</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{packet} (set {parameter})</source>
        <translation>{packet} (écriture de {parameter})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the firmware forces driving_mechanism to 1 after every set</source>
        <translation>le firmware impose driving_mechanism à 1 après chaque écriture</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the firmware recomputes {parameter} after every set: this value will not stay (it holds {held:g})</source>
        <translation>le firmware recalcule {parameter} après chaque écriture&#xa0;: cette valeur ne restera pas (il vaut {held:g})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the firmware recomputes {parameter} at every move: this value will not stay</source>
        <translation>le firmware recalcule {parameter} à chaque mouvement&#xa0;: cette valeur ne restera pas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>this firmware revision reads {parameter} only at boot: moves do not change until the device restarts</source>
        <translation>cette révision du firmware ne lit {parameter} qu&apos;au démarrage&#xa0;: les mouvements ne changent pas tant que l&apos;appareil n&apos;a pas redémarré</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>this firmware revision never reads {parameter}: moves do not change</source>
        <translation>cette révision du firmware ne lit jamais {parameter}&#xa0;: les mouvements ne changent pas</translation>
    </message>
    <message>
        <location line="-75"/>
        <source>Steps per move</source>
        <translation>Pas par mouvement</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X: 1 mm = {x1}, 10 mm = {x10} · Y: 1 mm = {y1}, 10 mm = {y10} (truncated: the firmware counts in 32-bit floats)</source>
        <translation>X&#xa0;: 1 mm = {x1}, 10 mm = {x10} · Y&#xa0;: 1 mm = {y1}, 10 mm = {y10} (tronqué&#xa0;: le firmware compte en flottants 32 bits)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{steps} steps, {stepping} s of stepping; FA0001 about {total} s after the packet</source>
        <translation>{steps} pas, {stepping} s d&apos;exécution des pas&#xa0;; FA0001 environ {total} s après le paquet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{text}; after a move in which Y stepped, {later} s (X&apos;s low phase is Y&apos;s last delay, {delay} µs: the ramps do not restore the delays)</source>
        <translation>{text}&#xa0;; après un mouvement où Y a fait des pas, {later} s (la phase basse de X est le dernier délai de Y, {delay} µs&#xa0;: les rampes ne rétablissent pas les délais)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A 10 mm X move</source>
        <translation>Un mouvement X de 10 mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no: the firmware&apos;s Y loop runs the ramp count (R_y = 0 with these values), not the {asked} steps a 10 mm move asks for; set 22 and 24 so that the ramp length is above 0 (e.g. 22 = 6000, 24 = 1)</source>
        <translation>non&#xa0;: la boucle Y du firmware exécute le compte de rampe (R_y = 0 avec ces valeurs), et non les {asked} pas que demande un mouvement de 10 mm&#xa0;; régler 22 et 24 pour que la longueur de rampe soit supérieure à 0 (par ex. 22 = 6000, 24 = 1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{runs} of the {asked} steps of a 10 mm Y move, {seconds} s: the firmware&apos;s Y loop runs the ramp count R_y (at most the ramp length {ramp}), not the distance, and speeds up without slowing down</source>
        <translation>{runs} des {asked} pas d&apos;un mouvement Y de 10 mm, {seconds} s&#xa0;: la boucle Y du firmware exécute le compte de rampe R_y (au plus la longueur de rampe {ramp}), et non la distance, et accélère sans ralentir</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y moves</source>
        <translation>Y se déplace</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none: the ramp length is 0 on both axes (it follows 21 ÷ 23 and 13 - 11); every X step takes 15 high plus 16 low</source>
        <translation>aucune&#xa0;: la longueur de rampe est 0 sur les deux axes (elle découle de 21 ÷ 23 et de 13 - 11)&#xa0;; chaque pas X dure 15 à l&apos;état haut plus 16 à l&apos;état bas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X over {x} steps, Y over {y} steps, between 13/14 (slow) and 11/12 (fast)</source>
        <translation>X sur {x} pas, Y sur {y} pas, entre 13/14 (lent) et 11/12 (rapide)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ramps</source>
        <translation>Rampes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not used</source>
        <translation>Non utilisés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{names}: the values in the table differ from power-on, but this firmware does not use them</source>
        <translation>{names}&#xa0;: les valeurs du tableau diffèrent de celles de la mise sous tension, mais ce firmware ne les utilise pas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Overwritten after every set</source>
        <translation>Écrasés après chaque écriture</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{ids}: the firmware recomputes them; a written value does not stay</source>
        <translation>{ids}&#xa0;: le firmware les recalcule&#xa0;; une valeur écrite ne reste pas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Overwritten at every move</source>
        <translation>Écrasés à chaque mouvement</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{ids}: the ramp counts of the last move</source>
        <translation>{ids}&#xa0;: les comptes de rampe du dernier mouvement</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Never read</source>
        <translation>Jamais lus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{ids}: writing them changes nothing (27 is forced to 1 after every set)</source>
        <translation>{ids}&#xa0;: les écrire ne change rien (27 est remis à 1 après chaque écriture)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read only at boot</source>
        <translation>Lus seulement au démarrage</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{ids}: the cycle length ({cycle} mm) is taken from them at power-on, when they hold their power-on values again: writing them changes no move</source>
        <translation>{ids}&#xa0;: la longueur de cycle ({cycle} mm) en est tirée à la mise sous tension, quand ils ont retrouvé leurs valeurs de mise sous tension&#xa0;: les écrire ne change aucun mouvement</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the firmware recomputes {id} after every set: this value will not stay</source>
        <translation>le firmware recalcule {id} après chaque écriture&#xa0;: cette valeur ne restera pas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the firmware recomputes {id} at every move: this value will not stay</source>
        <translation>le firmware recalcule {id} à chaque mouvement&#xa0;: cette valeur ne restera pas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the firmware forces 27 to 1 after every set: this value will not stay</source>
        <translation>le firmware impose 27 à 1 après chaque écriture&#xa0;: cette valeur ne restera pas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>this firmware never reads {id:02d}: writing it changes nothing</source>
        <translation>ce firmware ne lit jamais {id:02d}&#xa0;: l&apos;écrire ne change rien</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a move with ramps (ramp length above 0) leaves {id} at the ramp&apos;s last delay: this value stays only until then</source>
        <translation>un mouvement avec rampes (longueur de rampe supérieure à 0) laisse {id} au dernier délai de la rampe&#xa0;: cette valeur ne reste que jusque-là</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>this firmware reads {id:02d} only at boot, when it holds {value} again: writing it changes no move</source>
        <translation>ce firmware ne lit {id:02d} qu&apos;au démarrage, quand il vaut de nouveau {value}&#xa0;: l&apos;écrire ne change aucun mouvement</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Current step delay, {axis} axis (left by the firmware&apos;s ramps; this revision times an X step as 15 high plus 16 low, a Y step as 16 twice)</source>
        <translation>Délai entre pas actuel, axe {axis} (laissé par les rampes du firmware&#xa0;; cette révision cadence un pas X sur 15 à l&apos;état haut plus 16 à l&apos;état bas, un pas Y sur deux fois 16)</translation>
    </message>
    <message>
        <source>this firmware revision reads {parameter} only at boot (and keeps pulley values divided by 4): moves do not change until the firmware is fixed</source>
        <translation type="vanished">cette révision du firmware ne lit {parameter} qu&apos;au démarrage (et garde les valeurs de poulie divisées par 4)&#xa0;: les mouvements ne changent pas tant que le firmware n&apos;est pas corrigé</translation>
    </message>
    <message>
        <source>Note</source>
        <translation type="vanished">Remarque</translation>
    </message>
    <message>
        <source>this firmware revision moves by the cycle it computed at boot (10 mm lead screw), whatever 01-04 and 27 say</source>
        <translation type="vanished">cette révision du firmware se déplace selon le cycle calculé au démarrage (vis au pas de 10 mm), quelles que soient les valeurs de 01-04 et 27</translation>
    </message>
    <message>
        <source>{axis}: the cycle ({cycle:g} mm) and the steps per turn ({steps:g}) must both be above 0</source>
        <translation type="vanished">{axis}&#xa0;: le cycle ({cycle:g} mm) et les pas par tour ({steps:g}) doivent tous deux être supérieurs à 0</translation>
    </message>
    <message>
        <source>{times} (1 s silence included)</source>
        <translation type="vanished">{times} (1 s de silence inclus)</translation>
    </message>
    <message>
        <source>Microsteps per turn</source>
        <translation type="vanished">Micropas par tour</translation>
    </message>
    <message>
        <source>Per step</source>
        <translation type="vanished">Par pas</translation>
    </message>
    <message>
        <source>Steps per mm</source>
        <translation type="vanished">Pas par mm</translation>
    </message>
    <message>
        <source>A 10 mm move</source>
        <translation type="vanished">Un mouvement de 10 mm</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>Lead-screw pitch of the {axis} axis (mm per turn)</source>
        <translation>Pas de vis de l&apos;axe {axis} (mm par tour)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Belt pulley diameter of the {axis} axis; sent as mm×10 (38.2 mm -&gt; 000382)</source>
        <translation>Diamètre de la poulie de courroie de l&apos;axe {axis}&#xa0;; envoyé en mm×10 (38.2 mm -&gt; 000382)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Full steps per motor turn, {axis} axis</source>
        <translation>Pas entiers par tour moteur, axe {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Microstepping factor of the {axis} driver</source>
        <translation>Facteur de micropas du driver {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Highest speed allowed on the {axis} axis</source>
        <translation>Vitesse maximale autorisée sur l&apos;axe {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Step delay at the steady speed, {axis} axis (computed by the firmware)</source>
        <translation>Délai entre pas à vitesse stable, axe {axis} (calculé par le firmware)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Step delay at the lowest speed, {axis} axis</source>
        <translation>Délai entre pas à la vitesse minimale, axe {axis}</translation>
    </message>
    <message>
        <source>Current step delay, {axis} axis (computed by the firmware; this revision times every step from it: one step is twice this delay)</source>
        <translation type="vanished">Délai entre pas actuel, axe {axis} (calculé par le firmware&#xa0;; cette révision cadence chaque pas sur lui&#xa0;: un pas dure deux fois ce délai)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mean step delay while accelerating, {axis} axis (computed by the firmware)</source>
        <translation>Délai moyen entre pas pendant l&apos;accélération, axe {axis} (calculé par le firmware)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Steps spent accelerating, {axis} axis (computed by the firmware)</source>
        <translation>Pas effectués en accélération, axe {axis} (calculé par le firmware)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Requested steady speed of the {axis} axis</source>
        <translation>Vitesse stable demandée pour l&apos;axe {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Requested acceleration of the {axis} axis</source>
        <translation>Accélération demandée pour l&apos;axe {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Duration of the last move, {axis} axis (computed by the firmware)</source>
        <translation>Durée du dernier mouvement, axe {axis} (calculée par le firmware)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0 belt pulley, 1 lead screw (this firmware forces 1 after every set)</source>
        <translation>0 poulie et courroie, 1 vis (ce firmware impose 1 après chaque écriture)</translation>
    </message>
    <message>
        <source>protocol {name!r} is not implemented yet</source>
        <translation type="vanished">le protocole {name!r} n&apos;est pas encore implémenté</translation>
    </message>
    <message>
        <location line="-44"/>
        <source>unknown protocol {name!r} (known: {known})</source>
        <translation>protocole inconnu {name!r} (connus&#xa0;: {known})</translation>
    </message>
    <message>
        <location line="+105"/>
        <source>{protocol} has no stop command: the device finishes what it was sent</source>
        <translation>{protocol} n&apos;a pas de commande d&apos;arrêt&#xa0;: l&apos;appareil termine ce qui lui a été envoyé</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timeout {timeout:g} s refused: it must be positive</source>
        <translation>délai d&apos;attente de {timeout:g} s refusé&#xa0;: il doit être positif</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>variant {variant!r} asked for a protocol made as {chosen!r}</source>
        <translation>variante {variant!r} demandée pour un protocole créé avec la variante {chosen!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>baud {baud} refused: a positive number of bits per second</source>
        <translation>débit de {baud} bauds refusé&#xa0;: un nombre positif de bits par seconde est attendu</translation>
    </message>
    <message>
        <location line="+91"/>
        <source>capture with spy&apos;s default hexdump format: spy://PORT?file=FILE, without raw</source>
        <translation>capturer au format hexdump par défaut de spy&#xa0;: spy://PORT?file=FILE, sans raw</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>both directions run together, nothing tells TX from RX</source>
        <translation>les deux sens sont mêlés, rien ne distingue TX de RX</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {number}: spy&apos;s raw format is refused ({why}); {hint}</source>
        <translation>{source} ligne {number}&#xa0;: le format raw de spy est refusé ({why})&#xa0;; {hint}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {number}: not a pyserial spy:// hexdump line: {line!r}</source>
        <translation>{source} ligne {number}&#xa0;: pas une ligne hexdump pyserial spy://&#xa0;: {line!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {number}: bytes at offset {offset:#06x} of a {direction} call whose earlier lines are missing</source>
        <translation>{source} ligne {number}&#xa0;: octets à l&apos;offset {offset:#06x} d&apos;un appel {direction} dont les lignes précédentes manquent</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no traffic in it, only control-line events</source>
        <translation>{source}&#xa0;: aucun trafic, seulement des événements de lignes de contrôle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no traffic in it (nor spy&apos;s raw format); {hint}</source>
        <translation>{source}&#xa0;: aucun trafic (ni format raw de spy)&#xa0;; {hint}</translation>
    </message>
    <message>
        <location line="-25"/>
        <source>{error} (after {rounds} rounds; {acknowledged} of {total} instructions were acknowledged before it)</source>
        <translation>{error} (après {rounds} séries de tentatives&#xa0;; {acknowledged} instructions sur {total} avaient été acquittées auparavant)</translation>
    </message>
    <message>
        <location line="-179"/>
        <source>protocol {name!r} cannot be loaded: {error}</source>
        <translation>le protocole {name!r} ne peut pas être chargé : {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>protocol {name!r}: {target} is not a protocol class</source>
        <translation>protocole {name!r} : {target} n’est pas une classe de protocole</translation>
    </message>
    <message>
        <location line="+98"/>
        <source>{source}: {why}</source>
        <translation>{source}&#xa0;: {why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: device {device!r}: {why}</source>
        <translation>{where}&#xa0;: appareil {device!r}&#xa0;: {why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bench file</source>
        <translation>fichier de banc</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{path}: no device {name!r} (the bench has {names})</source>
        <translation>{path}&#xa0;: pas d&apos;appareil {name!r} (le banc a {names})</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>{name}</source>
        <translation>{name}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: more than {count:,} steps (lines, arcs and travel moves)</source>
        <translation>{where}&#xa0;: plus de {count:,} étapes (lignes, arcs et déplacements à vide)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: a coordinate that is not a finite number</source>
        <translation>{where}&#xa0;: une coordonnée qui n&apos;est pas un nombre fini</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>chord tolerance {tolerance:g} mm must be above 0</source>
        <translation>la tolérance de corde {tolerance:g} mm doit être supérieure à 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DXF drawing</source>
        <translation>Dessin DXF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: not a drawing the panel reads: {why}</source>
        <translation>{where}&#xa0;: pas un dessin que le panneau sait lire&#xa0;: {why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: no lines, arcs or curves on the chosen layers</source>
        <translation>{name}&#xa0;: aucune ligne, aucun arc ni aucune courbe sur les calques choisis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: skipped what is not a path: {what}</source>
        <translation>{name}&#xa0;: ignoré ce qui n&apos;est pas un tracé&#xa0;: {what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: binary DXF cut short (no EOF at its end)</source>
        <translation>{name}&#xa0;: DXF binaire tronqué (pas d&apos;EOF à la fin)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: a DWG drawing, not DXF (save it as DXF)</source>
        <translation>{name}&#xa0;: un dessin DWG, pas DXF (l&apos;enregistrer en DXF)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: not a DXF drawing the panel reads: {why}</source>
        <translation>{name}&#xa0;: pas un dessin DXF que le panneau sait lire&#xa0;: {why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: $INSUNITS {value!r} is not a unit code</source>
        <translation>{name}&#xa0;: $INSUNITS {value!r} n&apos;est pas un code d&apos;unité</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: no units given ($INSUNITS 0), taken as mm</source>
        <translation>{name}&#xa0;: aucune unité indiquée ($INSUNITS 0), mm par défaut</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: units $INSUNITS {code} the panel cannot convert to mm</source>
        <translation>{name}&#xa0;: unités $INSUNITS {code} que le panneau ne sait pas convertir en mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} entity {number} ({kind} on layer {layer}): not a drawing the panel reads: {why}</source>
        <translation>{name} entité {number} ({kind} sur le calque {layer})&#xa0;: pas un dessin que le panneau sait lire&#xa0;: {why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: no layer {layer} with lines, arcs or curves; the drawing&apos;s layers: {layers}</source>
        <translation>{name}&#xa0;: aucun calque {layer} avec des lignes, arcs ou courbes&#xa0;; calques du dessin&#xa0;: {layers}</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>{name} line {number}</source>
        <translation>{name} ligne {number}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: a comment opened with ( is not closed</source>
        <translation>{where}&#xa0;: un commentaire ouvert par ( n&apos;est pas fermé</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word} with R: a full circle needs I/J</source>
        <translation>{where}&#xa0;: {word} avec R&#xa0;: un cercle complet exige I/J</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word}: R {radius:g} mm is less than half the way to the end point ({half:g} mm)</source>
        <translation>{where}&#xa0;: {word}&#xa0;: R {radius:g} mm est inférieur à la moitié de la distance jusqu&apos;au point d&apos;arrivée ({half:g} mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word}: the feed rate must be above 0</source>
        <translation>{where}&#xa0;: {word}&#xa0;: la vitesse d&apos;avance doit être supérieure à 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word} needs P, the seconds to dwell</source>
        <translation>{where}&#xa0;: {word} exige P, la durée de temporisation en secondes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word}: a dwell cannot be negative</source>
        <translation>{where}&#xa0;: {word}&#xa0;: une temporisation ne peut pas être négative</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word} with no motion mode (G0, G1, G2 or G3) set</source>
        <translation>{where}&#xa0;: {word} sans mode de mouvement (G0, G1, G2 ou G3) défini</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: no feed rate (F) set before this {word}</source>
        <translation>{where}&#xa0;: aucune vitesse d&apos;avance (F) définie avant ce {word}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: no moves and no dwells</source>
        <translation>{name}&#xa0;: aucun mouvement et aucune temporisation</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word}: arcs in the {plane} plane ({code}) are not supported: only G17 (XY)</source>
        <translation>{where}&#xa0;: {word}&#xa0;: les arcs dans le plan {plane} ({code}) ne sont pas pris en charge&#xa0;: seulement G17 (XY)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word} needs I and J, or R</source>
        <translation>{where}&#xa0;: {word} exige I et J, ou R</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word}: the centre is {start:g} mm from the start point and {end:g} mm from the end point, not on one circle</source>
        <translation>{where}&#xa0;: {word}&#xa0;: le centre est à {start:g} mm du point de départ et à {end:g} mm du point d&apos;arrivée, pas sur un même cercle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word}: an arc of radius 0</source>
        <translation>{where}&#xa0;: {word}&#xa0;: un arc de rayon 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word} is not used by anything on the line</source>
        <translation>{where}&#xa0;: {word} n&apos;est utilisé par rien sur la ligne</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {first} and {second} cannot be on one line</source>
        <translation>{where}&#xa0;: {first} et {second} ne peuvent pas figurer sur une même ligne</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>{name}: more than {count:,} lines, too many for a program</source>
        <translation>{name}&#xa0;: plus de {count:,} lignes, trop pour un programme</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word!r} is not a G-code word (a letter and a number)</source>
        <translation>{where}&#xa0;: {word!r} n&apos;est pas un mot G-code (une lettre et un nombre)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word} is not understood</source>
        <translation>{where}&#xa0;: {word} n&apos;est pas compris</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: skipped what the panel does not do: {words} (on {count} of {total} lines)</source>
        <translation>{name}&#xa0;: ignoré ce que le panneau ne fait pas&#xa0;: {words} (sur {count} des {total} lignes)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>chord tolerance {value:g} mm refused: it must be above 0</source>
        <translation>tolérance de corde {value:g} mm refusée&#xa0;: elle doit être supérieure à 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: the program moves {axis} to {value:g} mm, an axis the device does not have (it has {axes}); nothing was sent</source>
        <translation>{where}&#xa0;: le programme déplace {axis} à {value:g} mm, un axe que l&apos;appareil n&apos;a pas (il a {axes})&#xa0;; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>{where}: the program would leave the travel box at ({x:g}, {y:g}, {z:g}) mm ({box}); nothing was sent</source>
        <translation>{where}&#xa0;: le programme sortirait de la zone de course en ({x:g}, {y:g}, {z:g}) mm ({box})&#xa0;; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: layers are chosen in DXF files only</source>
        <translation>{file}&#xa0;: les calques ne se choisissent que dans les fichiers DXF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} entity {number} ({text})</source>
        <translation>{name} entité {number} ({text})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} element {number} ({text})</source>
        <translation>{name} élément {number} ({text})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} point {number}</source>
        <translation>{name} point {number}</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>{where}: speed {speed:g} mm/s refused: the device allows {low:g} to {high:g} mm/s; nothing was sent</source>
        <translation>{where}&#xa0;: vitesse {speed:g} mm/s refusée&#xa0;: l&apos;appareil accepte de {low:g} à {high:g} mm/s&#xa0;; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <location line="-513"/>
        <source>{command} refused: the stepper is not configured for {port} (the board forgets it at each reset, and none is kept for this port); run motionctl --port {port} --protocol firmata config --steps-per-rev 200 --pins 8 9 with your motor&apos;s steps per revolution and pins (or Configure in the panel&apos;s Stepper setup): it is kept and sent again at each run</source>
        <translation>{command} refusé&#xa0;: le moteur pas à pas n&apos;est pas configuré pour {port} (la carte l&apos;oublie à chaque réinitialisation, et aucune configuration n&apos;est conservée pour ce port)&#xa0;; lancer motionctl --port {port} --protocol firmata config --steps-per-rev 200 --pins 8 9 avec le nombre de pas par tour et les broches de votre moteur (ou «&#xa0;Configurer&#xa0;» dans la Configuration du moteur du panneau)&#xa0;: elle est conservée et renvoyée à chaque exécution</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>{file} names no protocol (no connection note) and no protocol recognises its traffic: give --protocol</source>
        <translation>{file} n&apos;indique aucun protocole (pas de note de connexion) et aucun protocole ne reconnaît son trafic&#xa0;: indiquer --protocol</translation>
    </message>
    <message>
        <location line="+388"/>
        <source>The speed cannot be set here: this firmware revision times its steps from step_delay_instantaneous (15, 16) alone, not from input_speed_steady (21, 22). &quot;device:&quot; is the speed X steps at (15 high plus 16 low a step); change 15 and 16 in the parameter table to change it.</source>
        <translation>La vitesse ne peut pas être réglée ici&#xa0;: cette révision du firmware cadence ses pas uniquement sur step_delay_instantaneous (15, 16), et non sur input_speed_steady (21, 22). «&#xa0;appareil&#xa0;:&#xa0;» est la vitesse à laquelle X fait ses pas (15 à l&apos;état haut plus 16 à l&apos;état bas par pas)&#xa0;; modifier 15 et 16 dans le tableau des paramètres pour la changer.</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Y will not move: at these parameters the firmware&apos;s Y loop makes no step (it runs the ramp count, 0; set 22 and 24 so that the ramp length is above 0)</source>
        <translation>Y ne bougera pas&#xa0;: avec ces paramètres, la boucle Y du firmware ne fait aucun pas (elle exécute le compte de rampe, 0&#xa0;; régler 22 et 24 pour que la longueur de rampe soit supérieure à 0)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y moves {moved:.3f} mm, not {asked:.3f}: the firmware&apos;s Y loop runs the ramp count ({loops} of {steps} steps)</source>
        <translation>Y se déplace de {moved:.3f} mm, et non de {asked:.3f}&#xa0;: la boucle Y du firmware exécute le compte de rampe ({loops} pas sur {steps})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} moves {moved:.3f} mm, not {asked:.3f}: whole steps ({steps}), truncated as the firmware counts</source>
        <translation>{axis} se déplace de {moved:.3f} mm, et non de {asked:.3f}&#xa0;: pas entiers ({steps}), tronqués comme les compte le firmware</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>{protocol} reports where it is: it is asked</source>
        <translation>{protocol} indique où il se trouve&#xa0;: il est interrogé</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>the program&apos;s moves without a speed would go at the device&apos;s speed, {speed:g} mm/s, outside the {low:g} to {high:g} mm/s it allows: set the speed first; nothing was sent</source>
        <translation>les mouvements du programme sans vitesse se feraient à la vitesse de l&apos;appareil, {speed:g} mm/s, hors de la plage de {low:g} à {high:g} mm/s qu&apos;il accepte&#xa0;: régler d&apos;abord la vitesse&#xa0;; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {error}; nothing was sent</source>
        <translation>{where}&#xa0;: {error}&#xa0;; rien n&apos;a été envoyé</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the program was abandoned during a dwell</source>
        <translation>le programme a été abandonné pendant une temporisation</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SVG scale {scale:g} mm per unit must be above 0</source>
        <translation>l&apos;échelle SVG {scale:g} mm par unité doit être supérieure à 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SVG drawing</source>
        <translation>Dessin SVG</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: not a shape the panel reads: {why}</source>
        <translation>{where}&#xa0;: pas une forme que le panneau sait lire&#xa0;: {why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: no stroked paths or shapes to run</source>
        <translation>{name}&#xa0;: aucun tracé ni aucune forme avec contour à exécuter</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: skipped {what}</source>
        <translation>{name}&#xa0;: ignoré {what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} line {line}: not SVG: {why}</source>
        <translation>{name} ligne {line}&#xa0;: pas du SVG&#xa0;: {why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: not an SVG drawing the panel reads: {why}</source>
        <translation>{name}&#xa0;: pas un dessin SVG que le panneau sait lire&#xa0;: {why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: not an SVG drawing (no svg element)</source>
        <translation>{name}&#xa0;: pas un dessin SVG (aucun élément svg)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: no width and height in mm, cm, in, pt, pc or px; 1 unit taken as {scale:g} mm</source>
        <translation>{name}&#xa0;: pas de largeur ni de hauteur en mm, cm, in, pt, pc ou px&#xa0;; 1 unité comptée pour {scale:g} mm</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>{pattern!r} is not a regular expression: {error}</source>
        <translation>{pattern!r} n&apos;est pas une expression régulière&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{pattern!r} is not valid text</source>
        <translation>{pattern!r} n&apos;est pas un texte valide</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{pattern!r}… is too large a regular expression: {error}</source>
        <translation>{pattern!r}… est une expression régulière trop grande&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="-353"/>
        <source>{url} is not open</source>
        <translation>{url} n&apos;est pas ouvert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>writing to {url} failed: {error}</source>
        <translation>échec de l&apos;écriture sur {url}&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>writing to {url}: only {written} of {total} bytes sent</source>
        <translation>écriture sur {url}&#xa0;: seuls {written} octets sur {total} ont été envoyés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reading from {url} failed: {error}</source>
        <translation>échec de la lecture sur {url}&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name!r} is not a line the host drives (DTR or RTS)</source>
        <translation>{name!r} n&apos;est pas une ligne pilotée par l&apos;hôte (DTR ou RTS)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{line} cannot be set</source>
        <translation>impossible de modifier {line}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>setting {line} on {url} failed: {error}</source>
        <translation>échec de la modification de {line} sur {url}&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the server did not confirm the control lines ({what} unanswered); they are set without confirmation (ser2net does not answer when the port it serves has no modem lines, e.g. a pseudo-terminal)</source>
        <translation>le serveur n&apos;a pas confirmé les lignes de contrôle ({what} sans réponse)&#xa0;; elles sont modifiées sans confirmation (ser2net ne répond pas quand le port qu&apos;il sert n&apos;a pas de lignes modem, par ex. un pseudo-terminal)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a break lasts more than 0 and at most {most:g} s</source>
        <translation>un break dure plus de 0 et au plus {most:g} s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no break can be sent</source>
        <translation>impossible d&apos;envoyer un break</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sending a break on {url} failed: {error}</source>
        <translation>échec de l&apos;envoi d&apos;un break sur {url}&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>break {ms:.0f} ms</source>
        <translation>break {ms:.0f} ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reading {line} on {url} failed: {error}</source>
        <translation>échec de la lecture de {line} sur {url}&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reading the control lines of {url} failed: {error}</source>
        <translation>échec de la lecture des lignes de contrôle de {url}&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a TCP socket</source>
        <translation>un socket TCP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{url} has no modem control lines ({why}): {what}</source>
        <translation>{url} n&apos;a pas de lignes de contrôle modem ({why})&#xa0;: {what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a pseudo-terminal</source>
        <translation>un pseudo-terminal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>its driver has no modem-line control</source>
        <translation>son pilote ne gère pas les lignes modem</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no port given</source>
        <translation>aucun port indiqué</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{url} is in use by another program</source>
        <translation>{url} est utilisé par un autre programme</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot open {url}: {error}</source>
        <translation>impossible d&apos;ouvrir {url}&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="-67"/>
        <source>travel limits need a range for each of x, y and z</source>
        <translation>les limites de course exigent une plage pour chacun de x, y et z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>travel limits for {axis} ({low:g} to {high:g} mm) are not a range: the minimum must be at most the maximum</source>
        <translation>les limites de course de {axis} ({low:g} à {high:g} mm) ne forment pas une plage&#xa0;: le minimum doit être inférieur ou égal au maximum</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the move</source>
        <translation>le mouvement</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} {value:g} mm is outside {low:g}..{high:g} mm</source>
        <translation>{axis} {value:g} mm est hors de {low:g}..{high:g} mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the stage is outside its travel limits: {what} brings it closer ({details})</source>
        <translation>la platine est hors de ses limites de course&#xa0;: {what} l&apos;en rapproche ({details})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what} refused: {details} (travel limits)</source>
        <translation>{what} refusé&#xa0;: {details} (limites de course)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what} clamped to the travel limits: {details}; going to ({x:g}, {y:g}, {z:g}) mm</source>
        <translation>{what} borné aux limites de course&#xa0;: {details}&#xa0;; déplacement vers ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>travel limits {text!r}: write three ranges in mm, X0:X1,Y0:Y1,Z0:Z1 (e.g. -100:100,-50:50,0:20), or none</source>
        <translation>limites de course {text!r}&#xa0;: indiquer trois plages en mm, X0:X1,Y0:Y1,Z0:Z1 (par ex. -100:100,-50:50,0:20), ou none</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>travel limits for {axis}: {part!r} is not MIN:MAX in mm (e.g. -100:100)</source>
        <translation>limites de course de {axis}&#xa0;: {part!r} n&apos;est pas de la forme MIN:MAX en mm (par ex. -100:100)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} {value!r} is not a finite number</source>
        <translation>{name} {value!r} n&apos;est pas un nombre fini</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} {value:g} mm refused: the device works to {resolution:g} mm (the nearest it can do is {nearest} mm)</source>
        <translation>{name} {value:g} mm refusé&#xa0;: l&apos;appareil a une résolution de {resolution:g} mm (la valeur possible la plus proche est {nearest} mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{earlier}; {later}</source>
        <translation>{earlier}&#xa0;; {later}</translation>
    </message>
    <message>
        <location line="+300"/>
        <source>expected a sim:// URL, got {url!r}</source>
        <translation>URL sim:// attendue, reçu {url!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown sim:// option {key!r}</source>
        <translation>option sim:// inconnue {key!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>port must be configured before it can be used</source>
        <translation>le port doit être configuré avant de pouvoir être utilisé</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>port already open</source>
        <translation>port déjà ouvert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot open {port}: {error}</source>
        <translation>impossible d&apos;ouvrir {port}&#xa0;: {error}</translation>
    </message>
    <message>
        <location line="-273"/>
        <source>{where} accepted this connection and closed it at once{said}: another client probably holds the port (ser2net serves one at a time with max-connections: 1); close it there first</source>
        <translation>{where} a accepté cette connexion et l&apos;a fermée aussitôt{said}&#xa0;: un autre client occupe probablement le port (ser2net n&apos;en sert qu&apos;un à la fois avec max-connections: 1)&#xa0;; fermer d&apos;abord ce client</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the server has not reported the modem lines</source>
        <translation>le serveur n&apos;a pas signalé l&apos;état des lignes modem</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nothing answers at {where} ({error}): is ser2net (or another RFC 2217 server) running there and serving that port?</source>
        <translation>rien ne répond à {where} ({error})&#xa0;: ser2net (ou un autre serveur RFC 2217) y tourne-t-il en servant ce port&#xa0;?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where} answers, but not as an RFC 2217 server: serve the port with ser2net&apos;s `accepter: telnet(rfc2217),tcp,PORT`, or open a raw TCP server as socket://{where}</source>
        <translation>{where} répond, mais pas en tant que serveur RFC 2217&#xa0;: servir le port avec la ligne ser2net `accepter: telnet(rfc2217),tcp,PORT`, ou ouvrir un serveur TCP brut via socket://{where}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timeout while waiting for option &apos;purge&apos;</source>
        <translation>délai dépassé en attendant l&apos;option &apos;purge&apos;</translation>
    </message>
    <message>
        <location line="-34"/>
        <source>no axis {axis!r}: x, y or z</source>
        <translation>pas d&apos;axe {axis!r}&#xa0;: x, y ou z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>work zero at home (work = machine)</source>
        <translation>zéro pièce à l&apos;origine (pièce = machine)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>work zero at ({x:g}, {y:g}, {z:g}) mm machine</source>
        <translation>zéro pièce à ({x:g}, {y:g}, {z:g}) mm machine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>work zero {text!r} is not three numbers x,y,z</source>
        <translation>le zéro pièce {text!r} n&apos;est pas formé de trois nombres x,y,z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>work zero {text!r} is not three finite numbers x,y,z</source>
        <translation>le zéro pièce {text!r} n&apos;est pas formé de trois nombres finis x,y,z</translation>
    </message>
</context>
</TS>
