<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es" sourcelanguage="en">
<context>
    <name>AboutDialog</name>
    <message>
        <location filename="../../widgets/about_dialog.py" line="+105"/>
        <source>About Motion Panel</source>
        <translation>Acerca de Motion Panel</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Motion Panel</source>
        <translation>Motion Panel</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Version %1</source>
        <translation>Versión %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown</source>
        <translation>desconocida</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A desktop control panel for serial stepper-motor positioning stages.</source>
        <translation>Panel de control de escritorio para platinas de posicionamiento con motores paso a paso por línea serie.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>see LICENSE</source>
        <translation>ver LICENSE</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Licence: %1</source>
        <translation>Licencia: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Components</source>
        <translation>Componentes</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>not installed</source>
        <translation>no instalado</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1:</source>
        <translation>%1:</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&amp;Copy details</source>
        <translation>&amp;Copiar detalles</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Copy the versions, e.g. for a bug report</source>
        <translation>Copiar las versiones, p. ej. para un informe de error</translation>
    </message>
</context>
<context>
    <name>ArcEntry</name>
    <message>
        <location filename="../../widgets/arc_entry.py" line="+274"/>
        <source>X of the arc&apos;s centre, in mm from home</source>
        <translation>X del centro del arco, en mm desde el origen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y of the arc&apos;s centre, in mm from home</source>
        <translation>Y del centro del arco, en mm desde el origen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Radius of the arc, in mm (more than 0)</source>
        <translation>Radio del arco, en mm (mayor que 0)</translation>
    </message>
    <message>
        <location line="-127"/>
        <source>Angle of the start point, 0 to 360°, counter-clockwise from +X seen from above</source>
        <translation>Ángulo del punto inicial, de 0 a 360°, en sentido antihorario desde +X visto desde arriba</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Angle of the end point, 0 to 360°, counter-clockwise from +X seen from above;
the same as the start angle: a full circle</source>
        <translation>Ángulo del punto final, de 0 a 360°, en sentido antihorario desde +X visto desde arriba;
igual al ángulo inicial: una circunferencia completa</translation>
    </message>
    <message>
        <location line="+120"/>
        <source>Z at the end of the arc, in mm; Z moves evenly from the current Z along the arc
(a helix when it differs)</source>
        <translation>Z al final del arco, en mm; Z avanza de forma uniforme desde la Z actual a lo largo del arco
(una hélice si es distinta)</translation>
    </message>
    <message>
        <location line="-96"/>
        <source>Centre X:</source>
        <translation>Centro X:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Centre Y:</source>
        <translation>Centro Y:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Radius:</source>
        <translation>Radio:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start:</source>
        <translation>Inicio:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>End:</source>
        <translation>Fin:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Final Z:</source>
        <translation>Z final:</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>CW</source>
        <translation>Horario</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Clockwise seen from above: the angle decreases</source>
        <translation>Sentido horario visto desde arriba: el ángulo disminuye</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CCW</source>
        <translation>Antihorario</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Counter-clockwise seen from above: the angle increases</source>
        <translation>Sentido antihorario visto desde arriba: el ángulo aumenta</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Preview</source>
        <translation>Vista previa</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Draw the arc, dashed, in the position views</source>
        <translation>Dibujar el arco, con línea discontinua, en las vistas de posición</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Run arc</source>
        <translation>Ejecutar arco</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+189"/>
        <source>Move along the arc, from its start point to its end point</source>
        <translation>Moverse a lo largo del arco, desde su punto inicial hasta su punto final</translation>
    </message>
    <message>
        <location line="-181"/>
        <source>Why the arc cannot run</source>
        <translation>Por qué no se puede ejecutar el arco</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>X of the arc&apos;s centre, in inches from home</source>
        <translation>X del centro del arco, en pulgadas desde el origen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y of the arc&apos;s centre, in inches from home</source>
        <translation>Y del centro del arco, en pulgadas desde el origen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Radius of the arc, in inches (more than 0)</source>
        <translation>Radio del arco, en pulgadas (mayor que 0)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Z at the end of the arc, in inches; Z moves evenly from the current Z along the arc
(a helix when it differs)</source>
        <translation>Z al final del arco, en pulgadas; Z avanza de forma uniforme desde la Z actual a lo largo del arco
(una hélice si es distinta)</translation>
    </message>
    <message>
        <location line="+148"/>
        <source>The radius must be more than 0 in.</source>
        <translation>El radio debe ser mayor que 0 in.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The radius must be more than 0 mm.</source>
        <translation>El radio debe ser mayor que 0 mm.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 %2 to %3 in (travel %4 to %5 in)</source>
        <translation>%1 de %2 a %3 in (recorrido de %4 a %5 in)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 %2 in (travel %3 to %4 in)</source>
        <translation>%1 %2 in (recorrido de %3 a %4 in)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 %2 to %3 mm (travel %4 to %5 mm)</source>
        <translation>%1 de %2 a %3 mm (recorrido de %4 a %5 mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 %2 mm (travel %3 to %4 mm)</source>
        <translation>%1 %2 mm (recorrido de %3 a %4 mm)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>The arc leaves the travel limits: %1.</source>
        <translation>El arco sale de los límites de recorrido: %1.</translation>
    </message>
</context>
<context>
    <name>BridgeSession</name>
    <message>
        <location filename="../../app/window/device/bridge_session.py" line="+93"/>
        <source>the bridge failed: %1</source>
        <translation>el puente falló: %1</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>the bridge stopped</source>
        <translation>el puente se detuvo</translation>
    </message>
</context>
<context>
    <name>CompactReadout</name>
    <message>
        <location filename="../../widgets/compact_readout.py" line="+34"/>
        <source>Stage position from the device&apos;s home</source>
        <translation>Posición de la platina desde el origen del dispositivo</translation>
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
        <translation>Desconectado</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connecting…</source>
        <translation>Conectando…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connected</source>
        <translation>Conectado</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Error</source>
        <translation>Error</translation>
    </message>
    <message>
        <location line="+93"/>
        <source>/dev/ttyUSB0, COM3 or a URL</source>
        <translation>/dev/ttyUSB0, COM3 o una URL</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Serial port, or any pyserial URL (e.g. sim://coxiris, socket://host:port, loop://)</source>
        <translation>Puerto serie, o cualquier URL de pyserial (p. ej. sim://coxiris, socket://host:port, loop://)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Look for serial ports again</source>
        <translation>Volver a buscar puertos serie</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The language the device speaks</source>
        <translation>El lenguaje que habla el dispositivo</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Variant:</source>
        <translation>Variante:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The wire variant of this protocol (packet format and rate)</source>
        <translation>La variante de transmisión de este protocolo (formato de paquete y velocidad)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Baud rate in bit/s (type any rate the device uses)</source>
        <translation>Velocidad en baudios, en bit/s (se puede escribir cualquier velocidad que use el dispositivo)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Bridge</source>
        <translation>Puente</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Bridge (snoop) mode: open the device&apos;s port and offer another program a pseudo-terminal; every byte is forwarded both ways unchanged and shown decoded here (motion controls are off while bridging)</source>
        <translation>Modo puente (espía): abrir el puerto del dispositivo y ofrecer a otro programa un pseudoterminal; cada byte se reenvía sin cambios en ambos sentidos y se muestra aquí decodificado (los controles de movimiento se desactivan mientras dura el puente)</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+6"/>
        <location line="+225"/>
        <source>Connect</source>
        <translation>Conectar</translation>
    </message>
    <message>
        <location line="-225"/>
        <location line="+224"/>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <location line="-224"/>
        <location line="+224"/>
        <source>Disconnect</source>
        <translation>Desconectar</translation>
    </message>
    <message>
        <location line="-216"/>
        <source>Lines:</source>
        <translation>Líneas:</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&amp;Port:</source>
        <translation>&amp;Puerto:</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation type="vanished">Puerto:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Protocol:</source>
        <translation>Protocolo:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Baud:</source>
        <translation>Baudios:</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>No description for this port</source>
        <translation>Sin descripción para este puerto</translation>
    </message>
    <message>
        <location line="+111"/>
        <source>● %1: %2</source>
        <translation>● %1: %2</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Open the port and talk to the device</source>
        <translation>Abrir el puerto y comunicarse con el dispositivo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Close the connection</source>
        <translation>Cerrar la conexión</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>choose or type a port</source>
        <translation>elegir o escribir un puerto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>choose a protocol</source>
        <translation>elegir un protocolo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the baud rate must be a positive whole number</source>
        <translation>la velocidad en baudios debe ser un número entero positivo</translation>
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
        <translation>Terminal de datos listo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Request To Send</source>
        <translation>Solicitud de envío</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear To Send</source>
        <translation>Listo para enviar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data Set Ready</source>
        <translation>Equipo de datos listo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Carrier Detect</source>
        <translation>Detección de portadora</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ring Indicator</source>
        <translation>Indicador de llamada</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Break</source>
        <translation>Break</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Send a break: hold the transmit line low for %1 ms (the device sees a framing error; some boards take it as a reset or attention signal)</source>
        <translation>Enviar un break: mantener la línea de transmisión en nivel bajo durante %1 ms (el dispositivo ve un error de trama; algunas placas lo interpretan como reinicio o señal de atención)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>The serial port&apos;s control lines</source>
        <translation>Líneas de control del puerto serie</translation>
    </message>
    <message>
        <location line="+49"/>
        <location line="+16"/>
        <source>%1 (%2): not connected</source>
        <translation>%1 (%2): no conectado</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>%1 (%2): this port cannot set %1</source>
        <translation>%1 (%2): este puerto no puede fijar %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (%2), driven by this computer: tick to assert it, untick to release it</source>
        <translation>%1 (%2), controlada por este equipo: marcar para activarla, desmarcar para liberarla</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>this port cannot report %1</source>
        <translation>este puerto no puede informar de %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2), driven by the device: on</source>
        <translation>%1 (%2), controlada por el dispositivo: activa</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2), driven by the device: off</source>
        <translation>%1 (%2), controlada por el dispositivo: inactiva</translation>
    </message>
</context>
<context>
    <name>CoordinateEntry</name>
    <message>
        <location filename="../../widgets/coordinate_entry.py" line="+34"/>
        <source>Make the current position the new home (0, 0, 0)?
All coordinates will be measured from here from now on.</source>
        <translation>¿Convertir la posición actual en el nuevo origen (0, 0, 0)?
A partir de ahora, todas las coordenadas se medirán desde aquí.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Motion Panel</source>
        <translation>Motion Panel</translation>
    </message>
    <message>
        <source>%1:</source>
        <comment>an axis field&apos;s label</comment>
        <translation type="vanished">%1:</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Absolute</source>
        <translation>Absoluto</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>Go to the typed coordinates (mm from home)</source>
        <translation>Ir a las coordenadas introducidas (mm desde el origen)</translation>
    </message>
    <message>
        <location line="-71"/>
        <source>Relative</source>
        <translation>Relativo</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>Move by the typed distances (mm) from where the stage is</source>
        <translation>Mover las distancias introducidas (mm) desde la posición actual de la platina</translation>
    </message>
    <message>
        <location line="-63"/>
        <source>Machine</source>
        <translation>Máquina</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Work</source>
        <translation>Trabajo</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>Which frame the typed coordinates are in: Machine (mm from the device&apos;s home) or Work (mm from the work zero); the device is always sent machine coordinates</source>
        <translation>Sistema de las coordenadas introducidas: Máquina (mm desde el origen del dispositivo) o Trabajo (mm desde el cero de pieza); al dispositivo siempre se le envían coordenadas de máquina</translation>
    </message>
    <message>
        <location line="-58"/>
        <source>Go</source>
        <translation>Ir</translation>
    </message>
    <message>
        <location line="-26"/>
        <source>&amp;%1:</source>
        <comment>an axis field&apos;s label; Alt+axis</comment>
        <translation>&amp;%1:</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Start the move (Enter in a field)</source>
        <translation>Iniciar el movimiento (Enter en un campo)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Use current</source>
        <translation>Usar actual</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fill the fields with the current position</source>
        <translation>Rellenar los campos con la posición actual</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Home</source>
        <translation>Origen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Run the homing sequence</source>
        <translation>Ejecutar la secuencia de búsqueda de origen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Set Home</source>
        <translation>Fijar origen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Make the current position the origin (asks first)</source>
        <translation>Convertir la posición actual en el origen (pide confirmación)</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+177"/>
        <source>Stop</source>
        <translation>Detener</translation>
    </message>
    <message>
        <location line="-177"/>
        <source>Stop the stage now</source>
        <translation>Detener la platina ahora</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the stage now (Esc)</source>
        <translation>Detener la platina ahora (Esc)</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Go to the typed coordinates (inches from home)</source>
        <translation>Ir a las coordenadas introducidas (pulgadas desde el origen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Move by the typed distances (inches) from where the stage is</source>
        <translation>Mover las distancias introducidas (pulgadas) desde la posición actual de la platina</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Which frame the typed coordinates are in: Machine (inches from the device&apos;s home) or Work (inches from the work zero); the device is always sent machine coordinates, in mm</source>
        <translation>Sistema de las coordenadas introducidas: Máquina (pulgadas desde el origen del dispositivo) o Trabajo (pulgadas desde el cero de pieza); al dispositivo siempre se le envían coordenadas de máquina, en mm</translation>
    </message>
    <message>
        <location line="+147"/>
        <source>Drop queued</source>
        <translation>Descartar cola</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1 distance to move, %2 to %3 in (%4)</source>
        <translation>Distancia a mover en %1, de %2 a %3 in (%4)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 target coordinate, %2 to %3 in (%4)</source>
        <translation>Coordenada de destino %1, de %2 a %3 in (%4)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 target coordinate in the work frame, %2 to %3 in (%4)</source>
        <translation>Coordenada de destino %1 en el sistema de trabajo, de %2 a %3 in (%4)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 distance to move, %2 to %3 mm (%4)</source>
        <translation>Distancia a mover en %1, de %2 a %3 mm (%4)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 target coordinate, %2 to %3 mm (%4)</source>
        <translation>Coordenada de destino %1, de %2 a %3 mm (%4)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 target coordinate in the work frame, %2 to %3 mm (%4)</source>
        <translation>Coordenada de destino %1 en el sistema de trabajo, de %2 a %3 mm (%4)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>travel limits</source>
        <translation>límites de recorrido</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no travel limits set</source>
        <translation>sin límites de recorrido definidos</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(this device has no such axis)</source>
        <translation>(este dispositivo no tiene ese eje)</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1; nothing sent</source>
        <translation>%1; no se ha enviado nada</translation>
    </message>
</context>
<context>
    <name>DerivedValues</name>
    <message>
        <location filename="../../widgets/parameter_table.py" line="+501"/>
        <source>Derived values</source>
        <translation>Valores derivados</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Computed from the values in the table, not read from the device</source>
        <translation>Calculados a partir de los valores de la tabla, no leídos del dispositivo</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>a parameter</source>
        <translation>un parámetro</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>needs a value for %1</source>
        <translation>necesita un valor para %1</translation>
    </message>
</context>
<context>
    <name>DeviceDocks</name>
    <message>
        <location filename="../../app/window/docks/device_docks.py" line="+93"/>
        <source>Not now: %1</source>
        <translation>Ahora no: %1</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>%1 on %2</source>
        <translation>%1 en %2</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>%1 to %2 mm on every axis (16-bit ticks)</source>
        <translation>%1 a %2 mm en cada eje (cuentas de 16 bits)</translation>
    </message>
    <message>
        <source>program %1: %2 points, nothing sent yet</source>
        <translation type="vanished">programa %1: %2 puntos, aún no se ha enviado nada</translation>
    </message>
    <message>
        <source>program saved to %1 (%2 points)</source>
        <translation type="vanished">programa guardado en %1 (%2 puntos)</translation>
    </message>
    <message>
        <source>the program stopped: %1</source>
        <translation type="vanished">el programa se detuvo: %1</translation>
    </message>
    <message>
        <source>program %1 done: %2/%3 executed, %4 frames, %5 retransmission(s), %6 s</source>
        <translation type="vanished">programa %1 terminado: %2/%3 ejecutadas, %4 tramas, %5 retransmisión(es), %6 s</translation>
    </message>
    <message>
        <source>program %1 stopped, the device&apos;s queue flushed: %2/%3 executed, %4 frames, %5 retransmission(s), %6 s</source>
        <translation type="vanished">programa %1 detenido, cola del dispositivo vaciada: %2/%3 ejecutadas, %4 tramas, %5 retransmisión(es), %6 s</translation>
    </message>
</context>
<context>
    <name>DockLayout</name>
    <message>
        <location filename="../../app/window/layout/dock_layout.py" line="+16"/>
        <source>Stepper setup</source>
        <translation>Configuración del motor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frame setup</source>
        <translation>Configuración del bastidor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Program</source>
        <translation>Programa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Arc</source>
        <translation>Arco</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dwell</source>
        <translation>Espera</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Travel limits</source>
        <translation>Límites de recorrido</translation>
    </message>
</context>
<context>
    <name>DwellEntry</name>
    <message>
        <location filename="../../widgets/dwell_entry.py" line="+28"/>
        <source>Dwell:</source>
        <translation>Espera:</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>How long the device waits, 0 to %1 ms; press Enter or Dwell to send</source>
        <translation>Tiempo de espera del dispositivo, de 0 a %1 ms; pulsar Enter o Esperar para enviar</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Dwell</source>
        <translation>Esperar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Make the device wait this long before its next command</source>
        <translation>Hacer que el dispositivo espere este tiempo antes de su siguiente comando</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1; nothing sent</source>
        <translation>%1; no se ha enviado nada</translation>
    </message>
</context>
<context>
    <name>FirmataPanel</name>
    <message>
        <location filename="../../widgets/firmata_panel.py" line="+31"/>
        <source>version unknown</source>
        <translation>versión desconocida</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Full steps per revolution of the motor, 1 to %1 (e.g. 200)</source>
        <translation>Pasos completos por revolución del motor, de 1 a %1 (p. ej. 200)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 pins</source>
        <translation>%1 pines</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>2 pins: a driver with step and direction inputs; 4 pins: the motor&apos;s four wires</source>
        <translation>2 pines: un driver con entradas de paso y dirección; 4 pines: los cuatro hilos del motor</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>pin </source>
        <translation>pin </translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Motor steps per mm of travel (more than 0): converts mm and mm/s to steps</source>
        <translation>Pasos del motor por mm de recorrido (mayor que 0): convierte mm y mm/s en pasos</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The speed in mm/s and the motor speed it means, in revolutions per minute</source>
        <translation>La velocidad en mm/s y la velocidad del motor correspondiente, en revoluciones por minuto</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Configure</source>
        <translation>Configurar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Set up the stepper on the board with these settings</source>
        <translation>Configurar el motor paso a paso de la placa con estos ajustes</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Library version</source>
        <translation>Versión de biblioteca</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ask the board for its stepper library&apos;s version</source>
        <translation>Pedir a la placa la versión de su biblioteca de motores paso a paso</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The stepper library version the board reported</source>
        <translation>La versión de la biblioteca de motores paso a paso que indicó la placa</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Steps/rev:</source>
        <translation>Pasos/rev:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Steps per mm:</source>
        <translation>Pasos por mm:</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Pins:</source>
        <translation>Pines:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The board&apos;s pin numbers (0 to %1) wired to the motor</source>
        <translation>Números de pin de la placa (0 a %1) conectados al motor</translation>
    </message>
    <message>
        <location line="+111"/>
        <source>step</source>
        <translation>paso</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>direction</source>
        <translation>dirección</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>motor wire</source>
        <translation>hilo del motor</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pin %1 (%2), 0 to %3</source>
        <translation>Pin %1 (%2), de 0 a %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not used</source>
        <translation>sin usar</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+2"/>
        <source>speed: %1 mm/s = %2 rpm</source>
        <translation>velocidad: %1 mm/s = %2 rpm</translation>
    </message>
</context>
<context>
    <name>Jobs</name>
    <message>
        <location filename="../../app/window/device/jobs.py" line="+25"/>
        <source>move to (%1, %2, %3) mm</source>
        <translation>mover a (%1, %2, %3) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>jog by (%1, %2, %3) %4</source>
        <translation>desplazar (%1, %2, %3) %4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>relative move by (%1, %2, %3) %4</source>
        <translation>movimiento relativo de (%1, %2, %3) %4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>go home</source>
        <translation>ir al origen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set home here</source>
        <translation>fijar el origen aquí</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set speed %1 mm/s</source>
        <translation>fijar velocidad %1 mm/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set %1 = %2 %3</source>
        <translation>fijar %1 = %2 %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>arc around (%1, %2) mm, radius %3 mm, from %4° to %5° CCW</source>
        <translation>arco alrededor de (%1, %2) mm, radio %3 mm, de %4° a %5° en sentido antihorario</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>arc around (%1, %2) mm, radius %3 mm, from %4° to %5° CW</source>
        <translation>arco alrededor de (%1, %2) mm, radio %3 mm, de %4° a %5° en sentido horario</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dwell %1 ms</source>
        <translation>esperar %1 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set %1</source>
        <translation>fijar %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>configure the stepper: %1 steps/rev on pins %2</source>
        <translation>configurar el motor paso a paso: %1 pasos/rev en los pines %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ask the stepper library version</source>
        <translation>pedir la versión de la biblioteca de motores paso a paso</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>run %1 (%2 points)</source>
        <translation>ejecutar %1 (%2 puntos)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>run %1 (%2 lines)</source>
        <translation>ejecutar %1 (%2 líneas)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>run %1 (%2 entities)</source>
        <translation>ejecutar %1 (%2 entidades)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>run %1 (%2 elements)</source>
        <translation>ejecutar %1 (%2 elementos)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>send &quot;%1&quot;</source>
        <translation>enviar &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>refresh position and speed</source>
        <translation>actualizar posición y velocidad</translation>
    </message>
</context>
<context>
    <name>JogPanel</name>
    <message>
        <location filename="../../widgets/jog_panel.py" line="+35"/>
        <source>Keys: ←/→ X, ↑/↓ Y, PgUp/PgDn Z, Shift ×10</source>
        <translation>Teclas: ←/→ X, ↑/↓ Y, PgUp/PgDn Z, Shift ×10</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Move the stage by one step; hold a button or key to keep stepping.
%1 (see the hint below for where the keys work).</source>
        <translation>Mover la platina un paso; mantener pulsado un botón o una tecla para seguir avanzando.
%1 (la indicación de abajo dice dónde funcionan las teclas).</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Step:</source>
        <translation>Paso:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Distance of one jog</source>
        <translation>Distancia de un desplazamiento</translation>
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
        <translation>Desplazar %1 por pulsación</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>%1 in</source>
        <translation>%1 in</translation>
    </message>
    <message>
        <location line="+131"/>
        <source>Any step size (%1 to %2 in)</source>
        <translation>Cualquier tamaño de paso (de %1 a %2 in)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Any step size (0.001 to 1000 mm)</source>
        <translation>Cualquier tamaño de paso (de 0.001 a 1000 mm)</translation>
    </message>
    <message>
        <location line="+174"/>
        <source>%1; no jog</source>
        <translation>%1; sin desplazamiento</translation>
    </message>
    <message>
        <location line="-256"/>
        <source>keys active</source>
        <translation>teclas activas</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>keys off: %1</source>
        <translation>teclas inactivas: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The jog keys work while this window is active and no menu, list, dialog or popup
is open, except when the focus is in a field that uses the arrow keys itself
(text and number fields, drop-down lists, the speed slider, the console).
Click the views or this panel to give the keys back to jogging.
Hold a key to keep stepping; Shift for a step ten times bigger.</source>
        <translation>Las teclas de desplazamiento funcionan mientras esta ventana está activa y no hay ningún menú,
lista, diálogo o ventana emergente abierto, salvo si el foco está en un campo que usa las flechas
(campos de texto y numéricos, listas desplegables, el control deslizante de velocidad, la consola).
Hacer clic en las vistas o en este panel para devolver las teclas al desplazamiento.
Mantener una tecla para seguir avanzando; Shift para un paso diez veces mayor.</translation>
    </message>
    <message>
        <location line="+103"/>
        <source>Jog %1 by %2 in (Shift: %3 in)</source>
        <translation>Desplazar %1 %2 in (Shift: %3 in)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Jog %1 by %2 mm (Shift: %3 mm)</source>
        <translation>Desplazar %1 %2 mm (Shift: %3 mm)</translation>
    </message>
</context>
<context>
    <name>KeyboardJog</name>
    <message>
        <location filename="../../app/window/keyboard_jog.py" line="+38"/>
        <source>a text field</source>
        <translation>un campo de texto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a number field</source>
        <translation>un campo numérico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a drop-down list</source>
        <translation>una lista desplegable</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a slider</source>
        <translation>un control deslizante</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a list or text view</source>
        <translation>una lista o vista de texto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a choice</source>
        <translation>una opción</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the menu bar</source>
        <translation>la barra de menús</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a menu</source>
        <translation>un menú</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tabs</source>
        <translation>las pestañas</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>not connected</source>
        <translation>no conectado</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>a menu or list is open</source>
        <translation>hay un menú o una lista abiertos</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a dialog is open</source>
        <translation>hay un diálogo abierto</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>another window is active</source>
        <translation>otra ventana está activa</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the focus is in %1</source>
        <translation>el foco está en %1</translation>
    </message>
</context>
<context>
    <name>LogViewer</name>
    <message>
        <location filename="../../app/window/console/log_viewer.py" line="+48"/>
        <source>(undecoded)</source>
        <translation>(sin decodificar)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Open traffic log</source>
        <translation>Abrir registro de tráfico</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Logs (*.log *.txt);;All files (*)</source>
        <translation>Registros (*.log *.txt);;Todos los archivos (*)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Traffic log</source>
        <translation>Registro de tráfico</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Decode with this protocol (chosen from the log&apos;s connection note when it has one)</source>
        <translation>Decodificar con este protocolo (elegido a partir de la nota de conexión del registro, si la tiene)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Open…</source>
        <translation>Abrir…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open a Motion Panel log or a pyserial spy:// capture</source>
        <translation>Abrir un registro de Motion Panel o una captura spy:// de pyserial</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no log open</source>
        <translation>ningún registro abierto</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Close</source>
        <translation>Cerrar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Close this log&apos;s window (Ctrl+W, Esc)</source>
        <translation>Cerrar la ventana de este registro (Ctrl+W, Esc)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Protocol:</source>
        <translation>Protocolo:</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>reading %1…</source>
        <translation>leyendo %1…</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>%1 — traffic log</source>
        <translation>%1 — registro de tráfico</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (%2): %3 lines, decoded as %4</source>
        <translation>%1 (%2): %3 líneas, decodificadas como %4</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>, recognised from its traffic (the log names no protocol)</source>
        <translation>, reconocido por su tráfico (el registro no indica ningún protocolo)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>; a simulator&apos;s record: TX and RX shown as the host saw them</source>
        <translation>; registro de un simulador: TX y RX mostrados como los vio el host</translation>
    </message>
</context>
<context>
    <name>MacroDock</name>
    <message>
        <location filename="../../app/window/docks/macro_dock.py" line="+30"/>
        <source>Motion Panel macros (*.json);;All files (*)</source>
        <translation>Macros de Motion Panel (*.json);;Todos los archivos (*)</translation>
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
        <translation>Pasos (uno por línea, cada uno espera al dispositivo): home · set-home · position · move X Y [Z] (mm) · jog DX DY [DZ] (mm) · speed V (mm/s) · raw TEXT (se envía tal cual y se espera su respuesta) · wait S (s, el panel hace una pausa) · check · id · limits; y si el dispositivo los admite: dwell MS (ms) · arc CX CY R START END --cw|--ccw · step RPM STEPS · status · stop · version.</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Macros (%1)</source>
        <translation>Macros (%1)</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1; nothing sent</source>
        <translation>%1; no se ha enviado nada</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>macro %1: step %2/%3: %4</source>
        <translation>macro %1: paso %2/%3: %4</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>choose a protocol first</source>
        <translation>elegir primero un protocolo</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a macro named %1 exists already</source>
        <translation>ya existe una macro llamada %1</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>macro %1 kept (%2 steps)</source>
        <translation>macro %1 guardada (%2 pasos)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>macro %1 deleted</source>
        <translation>macro %1 eliminada</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 macros; at most %2</source>
        <translation>%1 macros; como máximo %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>macros not imported: %1</source>
        <translation>macros no importadas: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>; %1 for other protocols left out</source>
        <translation>; %1 de otros protocolos omitidas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>imported %1 macro(s) from %2%3</source>
        <translation>%1 macro(s) importada(s) de %2%3</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>macros not exported: cannot write %1: %2</source>
        <translation>macros no exportadas: no se puede escribir %1: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>exported %1 macro(s) to %2</source>
        <translation>%1 macro(s) exportada(s) a %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Import macros</source>
        <translation>Importar macros</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Export macros</source>
        <translation>Exportar macros</translation>
    </message>
</context>
<context>
    <name>MacroEditor</name>
    <message>
        <location filename="../../widgets/macro_editor.py" line="+51"/>
        <source>Edit macro</source>
        <translation>Editar macro</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>New macro</source>
        <translation>Nueva macro</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The button&apos;s label: 1 to 40 characters</source>
        <translation>Etiqueta del botón: de 1 a 40 caracteres</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>One step per line, as motionctl takes it: distances in mm, speeds in mm/s, waits in s. Each step waits for the device&apos;s reply before the next.</source>
        <translation>Un paso por línea, tal como lo acepta motionctl: distancias en mm, velocidades en mm/s, esperas en s. Cada paso espera la respuesta del dispositivo antes del siguiente.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Delete</source>
        <translation>Eliminar</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Remove this macro</source>
        <translation>Eliminar esta macro</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Name:</source>
        <translation>&amp;Nombre:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Steps:</source>
        <translation>&amp;Pasos:</translation>
    </message>
</context>
<context>
    <name>MacroPanel</name>
    <message>
        <location filename="../../widgets/macro_panel.py" line="+37"/>
        <source>No macros yet: New… writes one, Import… reads a file.</source>
        <translation>Aún no hay macros: Nueva… crea una, Importar… lee un archivo.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>New…</source>
        <translation>Nueva…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Write a new macro</source>
        <translation>Escribir una macro nueva</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Edit</source>
        <translation>Editar</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Change or delete a macro</source>
        <translation>Modificar o eliminar una macro</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Import…</source>
        <translation>Importar…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add the macros of a file (JSON; data only, checked before any is kept)</source>
        <translation>Añadir las macros de un archivo (JSON; solo datos, se comprueban antes de guardar ninguna)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export…</source>
        <translation>Exportar…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Write this protocol&apos;s macros to a file</source>
        <translation>Escribir las macros de este protocolo en un archivo</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Run %1:
%2</source>
        <translation>Ejecutar %1:
%2</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Macros off: %1</source>
        <translation>Macros inactivas: %1</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <location filename="../../app/window/layout/fit_controls.py" line="+18"/>
        <source>%1 has no stop command: this drops the commands not yet sent; a move already under way on the device finishes (Esc)</source>
        <translation>%1 no tiene comando de parada: esto descarta los comandos aún no enviados; un movimiento ya en curso en el dispositivo termina (Esc)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Stop the stage now: halts the move under way and drops what is queued (Esc)</source>
        <translation>Detener la platina ahora: interrumpe el movimiento en curso y descarta lo que está en cola (Esc)</translation>
    </message>
    <message>
        <location filename="../../app/window/device/connection.py" line="+57"/>
        <source>simulated %1 device</source>
        <translation>dispositivo %1 simulado</translation>
    </message>
    <message>
        <location filename="../../app/window/main_window.py" line="+101"/>
        <source>Motion Panel</source>
        <translation>Motion Panel</translation>
    </message>
    <message>
        <location filename="../../app/window/device/worker_link.py" line="+113"/>
        <source>no session log: %1</source>
        <translation>sin registro de sesión: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>session log: %1</source>
        <translation>registro de sesión: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>no session log from now on</source>
        <translation>sin registro de sesión a partir de ahora</translation>
    </message>
    <message>
        <location filename="../../app/window/main_window.py" line="+130"/>
        <source>Connection</source>
        <translation>Conexión</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Position</source>
        <translation>Posición</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jog</source>
        <translation>Desplazamiento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Go to</source>
        <translation>Ir a</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed</source>
        <translation>Velocidad</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Console</source>
        <translation>Consola</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Parameters</source>
        <translation>Parámetros</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Traffic timeline</source>
        <translation>Línea de tiempo del tráfico</translation>
    </message>
    <message>
        <location filename="../../app/window/menus.py" line="+26"/>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export traffic log…</source>
        <translation>&amp;Exportar registro de tráfico…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save every byte sent and received, with timestamps, to a text file</source>
        <translation>Guardar cada byte enviado y recibido, con marcas de tiempo, en un archivo de texto</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Open log…</source>
        <translation>&amp;Abrir registro…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Browse a traffic log (ours or a pyserial spy:// capture) decoded</source>
        <translation>Ver decodificado un registro de tráfico (de este panel o una captura spy:// de pyserial)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Open the session &amp;log folder</source>
        <translation>Abrir la carpeta del &amp;registro de sesión</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Every byte of every session is kept there, one file a session</source>
        <translation>Allí se guarda cada byte de cada sesión, un archivo por sesión</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Motion</source>
        <translation>&amp;Movimiento</translation>
    </message>
    <message>
        <location filename="../../app/window/layout/fit_controls.py" line="+49"/>
        <location filename="../../app/window/menus.py" line="+1"/>
        <source>&amp;Stop</source>
        <translation>&amp;Detener</translation>
    </message>
    <message>
        <location filename="../../app/window/menus.py" line="+4"/>
        <source>&amp;Travel limits…</source>
        <translation>&amp;Límites de recorrido…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The box the stage may move in, for this device</source>
        <translation>La caja en la que puede moverse la platina, para este dispositivo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;View</source>
        <translation>&amp;Ver</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Reset views</source>
        <translation>&amp;Restablecer vistas</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Clear trail</source>
        <translation>&amp;Borrar trayectoria</translation>
    </message>
    <message>
        <location filename="../../app/window/device/connection.py" line="+76"/>
        <source>%1 names its protocol: connecting as %2</source>
        <translation>%1 indica su protocolo: conectando como %2</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>connecting to %1 (%2, %3 baud)</source>
        <translation>conectando con %1 (%2, %3 baudios)</translation>
    </message>
    <message>
        <location line="+88"/>
        <source>bridge refused: %1</source>
        <translation>puente rechazado: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>bridge: %1</source>
        <translation>puente: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>bridging %1 to %2</source>
        <translation>puente de %1 a %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bridge: another program can open %1; every byte goes to %2</source>
        <translation>puente: otro programa puede abrir %1; cada byte va a %2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>bridge ended: %1</source>
        <translation>puente terminado: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>bridge closed</source>
        <translation>puente cerrado</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>connection error: %1</source>
        <translation>error de conexión: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+9"/>
        <source>disconnected</source>
        <translation>desconectado</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>disconnected from %1 on %2</source>
        <translation>desconectado de %1 en %2</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>connected to %1 on %2</source>
        <translation>conectado a %1 en %2</translation>
    </message>
    <message>
        <location filename="../../app/window/device/machine_state.py" line="+38"/>
        <source>home set: the position is counted from here</source>
        <translation>origen fijado: la posición se cuenta desde aquí</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>an absolute point reached: the position is counted from here</source>
        <translation>punto absoluto alcanzado: la posición se cuenta desde aquí</translation>
    </message>
    <message>
        <location line="+53"/>
        <location line="+116"/>
        <source>the position is unknown: this device cannot report it; home it or set home</source>
        <translation>la posición es desconocida: este dispositivo no puede informar de ella; buscar el origen o fijar el origen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>connected again to %1: the position was read again</source>
        <translation>reconectado a %1: se ha vuelto a leer la posición</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the device cannot be asked where it is: it goes on from (%1, %2, %3) mm, where it was left on this port (kept, not measured)</source>
        <translation>no se puede preguntar al dispositivo dónde está: continúa desde (%1, %2, %3) mm, donde se dejó en este puerto (guardada, no medida)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>position unknown: the device cannot be asked; Home or Set Home to start counting</source>
        <translation>posición desconocida: no se puede consultar al dispositivo; pulsar Origen o Fijar origen para empezar a contar</translation>
    </message>
    <message>
        <location filename="../../app/window/layout/fit_controls.py" line="-41"/>
        <source>the device</source>
        <translation>el dispositivo</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Go to the home position (0, 0, 0)</source>
        <translation>Ir a la posición de origen (0, 0, 0)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Make the current position the origin (asks first)</source>
        <translation>Convertir la posición actual en el origen (pide confirmación)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Restart the panel&apos;s count of the position here (asks first); %1 has no set-home command, so nothing is sent</source>
        <translation>Reiniciar aquí el conteo de posición del panel (pide confirmación); %1 no tiene comando para fijar el origen, así que no se envía nada</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>&amp;Drop queued commands</source>
        <translation>&amp;Descartar comandos en cola</translation>
    </message>
    <message>
        <location filename="../../app/window/device/connection.py" line="+58"/>
        <source>port %1 appeared</source>
        <translation>apareció el puerto %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>reconnecting to %1</source>
        <translation>reconectando con %1</translation>
    </message>
    <message>
        <location line="-296"/>
        <source>port %1 disappeared</source>
        <translation>desapareció el puerto %1</translation>
    </message>
    <message>
        <location line="+309"/>
        <source>%1 on %2</source>
        <translation>%1 en %2</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>travel limits: %1</source>
        <translation>límites de recorrido: %1</translation>
    </message>
    <message>
        <location filename="../../app/window/device/job_desk.py" line="+115"/>
        <source>not connected: %1 not sent</source>
        <translation>no conectado: %1 sin enviar</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 refused: the position is unknown, so the program&apos;s coordinates would not be where it goes; Home or Set Home first</source>
        <translation>%1 rechazado: la posición es desconocida, así que las coordenadas del programa no corresponderían a donde va; haga primero Origen o Fijar origen</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 refused: the position is unknown and this device moves only to absolute targets, so it would go elsewhere; Set Home, Home or Go to first</source>
        <translation>%1 rechazado: la posición es desconocida y este dispositivo solo se mueve a destinos absolutos, así que iría a otro sitio; haga primero Fijar origen, Origen o Ir a</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 refused: %2 is under way; wait for its end or press Stop</source>
        <translation>se rechaza %1: %2 está en curso; esperar a que termine o pulsar Detener</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>motion controls are off until %1 ends (Stop ends it now)</source>
        <translation>los controles de movimiento están desactivados hasta que termine %1 (Detener lo termina ahora)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1 is under way</source>
        <translation>%1 está en curso</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>jog refused: %1</source>
        <translation>desplazamiento rechazado: %1</translation>
    </message>
    <message>
        <location line="+92"/>
        <source>Send unchecked bytes?</source>
        <translation>¿Enviar bytes sin comprobar?</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>These bytes cannot be read as a command (%1), so they cannot be checked against the travel limits (%2): they might move the stage outside them.

Send them anyway?</source>
        <translation>Estos bytes no se pueden interpretar como un comando (%1), así que no se pueden comprobar con los límites de recorrido (%2): podrían mover la platina fuera de ellos.

¿Enviarlos de todos modos?</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>not sent: the bytes could not be checked against the travel limits</source>
        <translation>sin enviar: los bytes no se pudieron comprobar con los límites de recorrido</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>stopping the macro under way</source>
        <translation>deteniendo la macro en curso</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>stopping the move under way</source>
        <translation>deteniendo el movimiento en curso</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>nothing queued; the move under way finishes</source>
        <translation>nada en cola; el movimiento en curso termina</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>stopped: %1 command(s) not sent: %2</source>
        <translation>detenido: %1 comando(s) sin enviar: %2</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../../app/window/device/machine_state.py" line="+65"/>
        <source>new home: the trail is shifted by (%1, %2, %3) mm</source>
        <translation>nuevo origen: la trayectoria se desplaza (%1, %2, %3) mm</translation>
    </message>
    <message>
        <location line="-147"/>
        <source>the device reported an error: %1</source>
        <translation>el dispositivo informó de un error: %1</translation>
    </message>
    <message>
        <location filename="../../app/window/device/connection.py" line="-125"/>
        <location filename="../../app/window/device/machine_state.py" line="+5"/>
        <source>device: %1</source>
        <translation>dispositivo: %1</translation>
    </message>
    <message>
        <location filename="../../app/window/device/job_desk.py" line="-11"/>
        <source>%1 failed: %2</source>
        <translation>%1 falló: %2</translation>
    </message>
    <message>
        <location filename="../../app/window/device/machine_state.py" line="-118"/>
        <source>home confirmed: the position is counted from here</source>
        <translation>origen confirmado: la posición se cuenta desde aquí</translation>
    </message>
    <message>
        <location line="+204"/>
        <source>position unknown: the device cannot be asked and its frames carry absolute targets, so a jog is refused; Set Home where the stage stands, Home, or Go to an absolute point first</source>
        <translation>posición desconocida: no se puede consultar al dispositivo y sus tramas llevan destinos absolutos, así que se rechaza el desplazamiento; pulsar primero Fijar origen donde está la platina, Origen, o Ir a un punto absoluto</translation>
    </message>
    <message>
        <location line="+206"/>
        <source>speed %1 mm/s reads back as %2 mm/s (the device rounds)</source>
        <translation>la velocidad %1 mm/s se relee como %2 mm/s (el dispositivo redondea)</translation>
    </message>
    <message>
        <location filename="../../app/window/layout/arrangements.py" line="+93"/>
        <source>&amp;Operate</source>
        <translation>&amp;Operar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Set up</source>
        <translation>&amp;Configurar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Traffic</source>
        <translation>Trá&amp;fico</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Jog, go to and watch the stage: the views large</source>
        <translation>Desplazar, ir a y observar la platina: las vistas en grande</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The device&apos;s parameters and setup panels, and macros</source>
        <translation>Los parámetros y paneles de configuración del dispositivo, y las macros</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The traffic console and its timeline, full width</source>
        <translation>La consola de tráfico y su línea de tiempo, a todo lo ancho</translation>
    </message>
    <message>
        <location filename="../../app/window/layout/layouts.py" line="+112"/>
        <source>Reset &amp;layout</source>
        <translation>Restablecer &amp;diseño</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Put the docks of this layout back as they were at first</source>
        <translation>Devolver los paneles de este diseño a su disposición inicial</translation>
    </message>
    <message>
        <location line="+274"/>
        <source>this device has parameters: %1 for Set up</source>
        <translation>este dispositivo tiene parámetros: %1 para Configurar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>this device has a setup panel: %1 for Set up</source>
        <translation>este dispositivo tiene un panel de configuración: %1 para Configurar</translation>
    </message>
    <message>
        <location filename="../../app/window/device/program_pause.py" line="+22"/>
        <source>paused: nothing more is sent; the move under way finishes (this device has no feed hold)</source>
        <translation>en pausa: no se envía nada más; el movimiento en curso termina (este dispositivo no tiene retención de avance)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>resumed: sending the program again</source>
        <translation>reanudado: se vuelve a enviar el programa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>paused: nothing more is sent; the device still holds %1 move(s) and runs them (its protocol has no feed hold): it stands still in about %2 s; Stop flushes them now</source>
        <translation>en pausa: no se envía nada más; el dispositivo aún tiene %1 movimiento(s) y los ejecuta (su protocolo no tiene retención de avance): se detendrá en unos %2 s; Detener los descarta ahora</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>paused: the device has run what it held; the stage stands still</source>
        <translation>en pausa: el dispositivo ha ejecutado lo que tenía; la platina está detenida</translation>
    </message>
</context>
<context>
    <name>NumberField</name>
    <message>
        <location filename="../../widgets/_number_field.py" line="+35"/>
        <source>a number is needed, %1 to %2%3</source>
        <translation>se necesita un número, de %1 a %2%3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1%2 is not a whole number</source>
        <translation>%1%2 no es un número entero</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>“%1” is not a number (%2 to %3%4)</source>
        <translation>“%1” no es un número (de %2 a %3%4)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1%4 is outside %2 to %3%4</source>
        <translation>%1%4 está fuera del rango de %2 a %3%4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1%2 has more than %3 decimals</source>
        <translation>%1%2 tiene más de %3 decimales</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1; cleared when the units changed to %2</source>
        <translation>%1; borrado al cambiar las unidades a %2</translation>
    </message>
</context>
<context>
    <name>ParameterDock</name>
    <message>
        <location filename="../../app/window/docks/parameter_dock.py" line="+34"/>
        <source>the device now holds %1: the firmware forces it after every set</source>
        <translation>el dispositivo tiene ahora %1: el firmware lo impone tras cada escritura</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>steps</source>
        <translation>pasos</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>Parameters</source>
        <translation>Parámetros</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>Parameters (%1)</source>
        <translation>Parámetros (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 on %2</source>
        <translation>%1 en %2</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>parameter writing cancelled: %1 not sent</source>
        <translation>escritura de parámetros cancelada: %1 sin enviar</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>not sent</source>
        <translation>sin enviar</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>recomputed by the firmware at the last move</source>
        <translation>recalculado por el firmware en el último movimiento</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the device did not answer</source>
        <translation>el dispositivo no respondió</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>connect to a device with parameters first</source>
        <translation>conectar primero a un dispositivo con parámetros</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>loaded %1 values from %2; nothing sent (Write changed sends them)</source>
        <translation>%1 valores cargados de %2; no se ha enviado nada (Escribir cambios los envía)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>left out, computed by the firmware: %1</source>
        <translation>omitidos, calculados por el firmware: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>saved %1 values to %2</source>
        <translation>%1 valores guardados en %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (firmware outputs are never saved)</source>
        <translation>%1 (las salidas del firmware nunca se guardan)</translation>
    </message>
</context>
<context>
    <name>ParameterEditor</name>
    <message>
        <location filename="../../widgets/parameter_editor.py" line="+49"/>
        <source>Parameter profiles (*.toml);;All files (*)</source>
        <translation>Perfiles de parámetros (*.toml);;Todos los archivos (*)</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>The device cannot be read back: this compares with what this panel last wrote</source>
        <translation>El dispositivo no se puede releer: se compara con lo último que escribió este panel</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Packets written so far; each is confirmed before the next</source>
        <translation>Paquetes escritos hasta ahora; cada uno se confirma antes del siguiente</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Write selected</source>
        <translation>Escribir selección</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write the values of the selected rows</source>
        <translation>Escribir los valores de las filas seleccionadas</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Write all</source>
        <translation>Escribir todo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write every value in the table, one packet each</source>
        <translation>Escribir todos los valores de la tabla, un paquete por valor</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Write changed</source>
        <translation>Escribir cambios</translation>
    </message>
    <message>
        <source>Write the values marked • (not yet written)</source>
        <translation type="vanished">Escribir los valores marcados con • (aún sin escribir)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop writing after the packet under way</source>
        <translation>Dejar de escribir tras el paquete en curso</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Load profile…</source>
        <translation>Cargar perfil…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fill the table from a file</source>
        <translation>Rellenar la tabla desde un archivo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save profile…</source>
        <translation>Guardar perfil…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Save the values to a file</source>
        <translation>Guardar los valores en un archivo</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Not loaded: %1</source>
        <translation>No cargado: %1</translation>
    </message>
    <message>
        <location line="+151"/>
        <source>nothing sent</source>
        <translation>no se ha enviado nada</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write finished: %1</source>
        <translation>Escritura terminada: %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 / %2 packets, about %3 left</source>
        <translation>%1 / %2 paquetes, quedan unos %3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no row selected</source>
        <translation>ninguna fila seleccionada</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the table has no values</source>
        <translation>la tabla no tiene valores</translation>
    </message>
    <message>
        <source>nothing differs</source>
        <translation type="vanished">no hay diferencias</translation>
    </message>
    <message>
        <location line="-238"/>
        <source>Write the input values marked • (they differ from what the device holds); firmware outputs are not written by it</source>
        <translation>Escribir los valores de entrada marcados con • (difieren de lo que tiene el dispositivo); no escribe las salidas del firmware</translation>
    </message>
    <message>
        <location line="+247"/>
        <source>no input differs</source>
        <translation>ninguna entrada difiere</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Nothing to write: %1</source>
        <translation>Nada que escribir: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Writing 1 value</source>
        <translation>Escribiendo 1 valor</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writing %1 values</source>
        <translation>Escribiendo %1 valores</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no value, not written: %1</source>
        <translation>sin valor, no escrito: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>computed by the firmware, which may replace them: %1</source>
        <translation>calculados por el firmware, que puede reemplazarlos: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Warning: %1</source>
        <translation>Aviso: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cancelling: the packet under way finishes, the rest are not sent</source>
        <translation>Cancelando: el paquete en curso termina, el resto no se envía</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Save parameter profile</source>
        <translation>Guardar perfil de parámetros</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Load parameter profile</source>
        <translation>Cargar perfil de parámetros</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>No parameters</source>
        <translation>Sin parámetros</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No values yet: load a profile or type them into the Value column</source>
        <translation>Aún no hay valores: cargar un perfil o escribirlos en la columna Valor</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>1 value differs from what was last written to this device (marked •)</source>
        <translation>1 valor difiere de lo último escrito en este dispositivo (marcado con •)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 values differ from what was last written to this device (marked •)</source>
        <translation>%1 valores difieren de lo último escrito en este dispositivo (marcados con •)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Every value is what was last written to this device</source>
        <translation>Todos los valores coinciden con lo último escrito en este dispositivo</translation>
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
        <translation>Nombre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit</source>
        <translation>Unidad</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Value</source>
        <translation>Valor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Last written</source>
        <translation>Último escrito</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Description</source>
        <translation>Descripción</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The value to write, in the unit beside it (double-click, F2, Enter or type)</source>
        <translation>El valor a escribir, en la unidad indicada al lado (doble clic, F2, Enter o escribir)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>What this panel last wrote to the device (the device cannot be read back)</source>
        <translation>Lo último que este panel escribió en el dispositivo (el dispositivo no se puede releer)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>input: set by you; output: computed by the firmware</source>
        <translation>entrada: la fija el usuario; salida: la calcula el firmware</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The outcome of the last write of this parameter</source>
        <translation>El resultado de la última escritura de este parámetro</translation>
    </message>
    <message>
        <location line="+92"/>
        <source>%1 (computed)</source>
        <translation>%1 (calculado)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 (power-on)</source>
        <translation>%1 (al encender)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>output</source>
        <translation>salida</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>input</source>
        <translation>entrada</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Input: set by you and written to the device</source>
        <translation>Entrada: la fija el usuario y se escribe en el dispositivo</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: never written to this device from this panel; it holds %2 from power-on</source>
        <translation>%1: nunca escrito en este dispositivo desde este panel; tiene %2 desde el encendido</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: never written to this device from this panel</source>
        <translation>%1: nunca escrito en este dispositivo desde este panel</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the device holds %2, computed by its firmware %3</source>
        <translation>%1: el dispositivo tiene %2, calculado por su firmware %3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: last written %2</source>
        <translation>%1: último valor escrito %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Allowed: %1</source>
        <translation>Permitido: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Value: %1</source>
        <translation>Valor: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>• Differs from what was last written to this device</source>
        <translation>• Difiere de lo último escrito en este dispositivo</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>%1: no such parameter</source>
        <translation>%1: no existe ese parámetro</translation>
    </message>
</context>
<context>
    <name>ParameterTableView</name>
    <message>
        <location line="+185"/>
        <source>Double-click a value, or select a row and press Enter or type, to edit</source>
        <translation>Para editar, hacer doble clic en un valor, o seleccionar una fila y pulsar Enter o escribir</translation>
    </message>
</context>
<context>
    <name>ParameterValues</name>
    <message>
        <location filename="../../widgets/parameter_values.py" line="+40"/>
        <source>not written</source>
        <translation>sin escribir</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pending</source>
        <translation>pendiente</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>confirmed</source>
        <translation>confirmado</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error</source>
        <translation>error</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timed out</source>
        <translation>tiempo agotado</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancelled</source>
        <translation>cancelado</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>after the last set</source>
        <translation>tras la última escritura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>at the last move</source>
        <translation>en el último movimiento</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Output: computed by the firmware. Writing it is allowed, but the firmware may replace what is written.</source>
        <translation>Salida: la calcula el firmware. Se permite escribirla, pero el firmware puede reemplazar lo escrito.</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1 to %2, whole numbers</source>
        <translation>de %1 a %2, números enteros</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 to %2 in steps of %3</source>
        <translation>de %1 a %2 en pasos de %3</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1: %2 refused (%3): %4</source>
        <translation>%1: %2 rechazado (%3): %4</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>empty</source>
        <translation>vacío</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>use a point for decimals</source>
        <translation>usar punto como separador decimal</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not a number</source>
        <translation>no es un número</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>not a finite number</source>
        <translation>no es un número finito</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>below the minimum</source>
        <translation>por debajo del mínimo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>above the maximum</source>
        <translation>por encima del máximo</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not a multiple of %1</source>
        <translation>no es múltiplo de %1</translation>
    </message>
</context>
<context>
    <name>PiFramePanel</name>
    <message>
        <location filename="../../widgets/piframe_panel.py" line="+17"/>
        <source>DTR on</source>
        <translation>DTR activa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DTR off</source>
        <translation>DTR inactiva</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DTR unknown</source>
        <translation>DTR desconocida</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Encoder ticks per mm of travel (more than 0): converts the frame&apos;s ticks to mm</source>
        <translation>Cuentas del encoder por mm de recorrido (mayor que 0): convierte las cuentas del bastidor en mm</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The state of the serial DTR line, which powers the frame</source>
        <translation>El estado de la línea serie DTR, que alimenta el bastidor</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The range the frame can reach, from its travel and ticks/mm</source>
        <translation>El rango que alcanza el bastidor, según su recorrido y sus cuentas/mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unknown</source>
        <translation>desconocido</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Ticks per mm:</source>
        <translation>Cuentas por mm:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DTR:</source>
        <translation>DTR:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reachable:</source>
        <translation>Alcance:</translation>
    </message>
</context>
<context>
    <name>PortWatcher</name>
    <message>
        <location filename="../../app/window/device/ports.py" line="+22"/>
        <source>serial port</source>
        <translation>puerto serie</translation>
    </message>
</context>
<context>
    <name>PositionReadout</name>
    <message>
        <location filename="../../widgets/position_readout.py" line="+26"/>
        <source>commanded, not measured</source>
        <translation>ordenada, no medida</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>commanded, move confirmed</source>
        <translation>ordenada, movimiento confirmado</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This device does not report its position: the numbers are where it was told to go.</source>
        <translation>Este dispositivo no informa de su posición: los valores indican adónde se le ordenó ir.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Where the device was told to go, and its reply said the move ended there; not read back (a device that can report its position is asked again when idle).</source>
        <translation>Adónde se le ordenó ir al dispositivo, y su respuesta indicó que el movimiento terminó allí; no se ha releído (a un dispositivo que puede informar de su posición se le vuelve a consultar en reposo).</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>position unknown: the device cannot be asked; Home or Set Home to start counting</source>
        <translation>posición desconocida: no se puede consultar al dispositivo; pulsar Origen o Fijar origen para empezar a contar</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>position unknown: the link failed or the device restarted, and it cannot report where it is; home it or set home</source>
        <translation>posición desconocida: el enlace falló o el dispositivo se reinició, y no puede informar de dónde está; buscar el origen o fijar el origen</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>estimated from the speed: the device cannot be asked while it moves</source>
        <translation>estimada a partir de la velocidad: no se puede consultar al dispositivo mientras se mueve</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>estimated when the link was lost, during a move: somewhere between its start and its target; not connected</source>
        <translation>estimada cuando se perdió el enlace, durante un movimiento: en algún punto entre su inicio y su destino; no conectado</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>bridging: no position seen in the bridged traffic yet (the panel asks nothing)</source>
        <translation>puente: aún no se ha visto ninguna posición en el tráfico del puente (el panel no pregunta nada)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>observed in the bridged traffic: the device reported this position to the other program</source>
        <translation>observada en el tráfico del puente: el dispositivo comunicó esta posición al otro programa</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>observed in the bridged traffic: the target of a move the other program sent, not confirmed by the device</source>
        <translation>observada en el tráfico del puente: el destino de un movimiento que envió el otro programa, no confirmado por el dispositivo</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>last known position: not connected</source>
        <translation>última posición conocida: no conectado</translation>
    </message>
    <message>
        <source>Stage position in mm: from the device&apos;s home, and from the work zero</source>
        <translation type="vanished">Posición de la platina en mm: desde el origen del dispositivo y desde el cero de pieza</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>Machine</source>
        <translation>Máquina</translation>
    </message>
    <message>
        <source>Millimetres from the device&apos;s home (its origin)</source>
        <translation type="vanished">Milímetros desde el origen del dispositivo (su posición de referencia)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Work</source>
        <translation>Trabajo</translation>
    </message>
    <message>
        <source>Millimetres from the work zero the panel keeps (the device is not told)</source>
        <translation type="vanished">Milímetros desde el cero de pieza que guarda el panel (no se comunica al dispositivo)</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Distances from the device&apos;s home (its origin)</source>
        <translation>Distancias desde el origen del dispositivo (su punto cero)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Distances from the work zero the panel keeps (the device is not told)</source>
        <translation>Distancias desde el cero de pieza que guarda el panel (el dispositivo no lo sabe)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Zero %1</source>
        <translation>Cero %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Make the current %1 the work zero (0 mm in the work frame); the device is not told, and its home stays where it is</source>
        <translation>Convertir la %1 actual en el cero de pieza (0 mm en el sistema de trabajo); no se comunica al dispositivo y su origen no cambia</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Zero all</source>
        <translation>Todo a cero</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Make the current position the work zero</source>
        <translation>Convertir la posición actual en el cero de pieza</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Clear zero</source>
        <translation>Borrar cero</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Put the work zero back at the device&apos;s home (work = machine)</source>
        <translation>Devolver el cero de pieza al origen del dispositivo (trabajo = máquina)</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>The stage is outside the travel limits set for this device: only moves that bring it closer to them are sent, until it is back inside</source>
        <translation>La platina está fuera de los límites de recorrido definidos para este dispositivo: solo se envían los movimientos que la acercan a ellos, hasta que vuelva a estar dentro</translation>
    </message>
    <message>
        <location line="+121"/>
        <source>outside the travel limits: %1</source>
        <translation>fuera de los límites de recorrido: %1</translation>
    </message>
    <message>
        <location line="+101"/>
        <source>millimetres</source>
        <translation>milímetros</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>inches</source>
        <translation>pulgadas</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stage position in %1: from the device&apos;s home, and from the work zero</source>
        <translation>Posición de la platina en %1: desde el origen del dispositivo y desde el cero de pieza</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>This device has no %1 axis</source>
        <translation>Este dispositivo no tiene eje %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Position unknown</source>
        <translation>Posición desconocida</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 position in %2 from the device&apos;s home</source>
        <translation>Posición %1 en %2 desde el origen del dispositivo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 position in %2 from the work zero</source>
        <translation>Posición %1 en %2 desde el cero de pieza</translation>
    </message>
    <message>
        <source>%1 position in mm from the device&apos;s home</source>
        <translation type="vanished">Posición %1 en mm desde el origen del dispositivo</translation>
    </message>
    <message>
        <source>%1 position in mm from the work zero</source>
        <translation type="vanished">Posición %1 en mm desde el cero de pieza</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>work zero: home</source>
        <translation>cero de pieza: origen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>work zero at (%1) %2 (machine)</source>
        <translation>cero de pieza en (%1) %2 (máquina)</translation>
    </message>
    <message>
        <source>work zero at %1 mm (machine)</source>
        <translation type="vanished">cero de pieza en %1 mm (máquina)</translation>
    </message>
</context>
<context>
    <name>PositionView2D</name>
    <message>
        <location filename="../../widgets/view2d/xy_plot.py" line="+27"/>
        <source>Stage seen from above: trail, current position (dot; hollow when estimated), target (+), travel limits (dashed)</source>
        <translation>Platina vista desde arriba: trayectoria, posición actual (punto; hueco si es estimada), destino (+), límites de recorrido (discontinuos)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>XY (from above)</source>
        <translation>XY (desde arriba)</translation>
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
        <translation>X, Y y Z en función del tiempo; líneas discontinuas: destino</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Position against time</source>
        <translation>Posición en función del tiempo</translation>
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
        <translation>tiempo (s, 0 = última muestra)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>t (s)</source>
        <translation>t (s)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>position (in)</source>
        <translation>posición (in)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>in</source>
        <translation>in</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position (mm)</source>
        <translation>posición (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <location line="-68"/>
        <source>Clear trail</source>
        <translation>Borrar trayectoria</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Forget the path so far (the current position stays)</source>
        <translation>Olvidar la trayectoria recorrida hasta ahora (la posición actual se mantiene)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reset view</source>
        <translation>Restablecer vista</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Zoom both plots to fit the data again</source>
        <translation>Volver a ajustar el zoom de ambos gráficos a los datos</translation>
    </message>
</context>
<context>
    <name>PositionView3D</name>
    <message>
        <location filename="../../widgets/view3d/navigation.py" line="+19"/>
        <source>Top</source>
        <translation>Superior</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>View from above (X right, Y up)</source>
        <translation>Vista desde arriba (X a la derecha, Y hacia arriba)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Front</source>
        <translation>Frontal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>View from the front (X right, Z up)</source>
        <translation>Vista frontal (X a la derecha, Z hacia arriba)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Side</source>
        <translation>Lateral</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>View from the side (Y right, Z up)</source>
        <translation>Vista lateral (Y a la derecha, Z hacia arriba)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Iso</source>
        <translation>Iso</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>View from above at an angle</source>
        <translation>Vista oblicua desde arriba</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Fit</source>
        <translation>Ajustar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zoom to the trail, the target and the workspace</source>
        <translation>Encuadrar la trayectoria, el destino y el espacio de trabajo</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Follow</source>
        <translation>Seguir</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep the camera on the current position</source>
        <translation>Mantener la cámara sobre la posición actual</translation>
    </message>
    <message>
        <location filename="../../widgets/view3d/notice.py" line="+15"/>
        <source>Needs OpenGL 2.1 or newer (e.g. Mesa) on a display; see the README.</source>
        <translation>Requiere OpenGL 2.1 o posterior (p. ej. Mesa) en una pantalla; ver el README.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>3D view unavailable: OpenGL could not be initialised.
(%1)
The 2D view shows the same positions.</source>
        <translation>Vista 3D no disponible: no se pudo inicializar OpenGL.
(%1)
La vista 2D muestra las mismas posiciones.</translation>
    </message>
    <message>
        <location filename="../../widgets/position_view_3d.py" line="+109"/>
        <source>Drag to rotate, wheel to zoom, middle-drag to pan</source>
        <translation>Arrastrar para girar, rueda para hacer zoom, arrastrar con el botón central para mover la vista</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>grid %1 in</source>
        <translation>cuadrícula %1 in</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>grid %1 mm</source>
        <translation>cuadrícula %1 mm</translation>
    </message>
</context>
<context>
    <name>Preferences</name>
    <message>
        <location filename="../../app/window/preferences.py" line="+67"/>
        <source>Stop (Motion menu)</source>
        <translation>Detener (menú Movimiento)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the console&apos;s next match</source>
        <translation>la siguiente coincidencia de la consola</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>moving the focus</source>
        <translation>mover el foco</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>connecting and sending</source>
        <translation>conectar y enviar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pressing the focused button</source>
        <translation>pulsar el botón que tiene el foco</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>Poll while moving</source>
        <translation>Consulta en movimiento</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Poll when idle</source>
        <translation>Consulta en reposo</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Console lines kept</source>
        <translation>Líneas conservadas en consola</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lines</source>
        <translation>líneas</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Session log</source>
        <translation>Registro de sesión</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Session log folder</source>
        <translation>Carpeta del registro de sesión</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Units shown</source>
        <translation>Unidades mostradas</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Decimals shown</source>
        <translation>Decimales mostrados</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>decimals</source>
        <translation>decimales</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Clamp moves to the limits</source>
        <translation>Ajustar los movimientos a los límites</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>smaller step</source>
        <translation>paso menor</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>larger step</source>
        <translation>paso mayor</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Theme</source>
        <translation>Tema</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Language</source>
        <translation>Idioma</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Jog key %1</source>
        <translation>Tecla de desplazamiento %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 to %2 %3</source>
        <translation>de %1 a %2 %3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: %2 lines is out of range: 0 (keep every line) or %3</source>
        <translation>%1: %2 líneas está fuera de rango: 0 (conservar todas las líneas) o %3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2 is out of range: -1 (as the device resolves) or %3</source>
        <translation>%1: %2 está fuera de rango: -1 (según la resolución del dispositivo) o %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2 %3 is out of range (%4)</source>
        <translation>%1: %2 %3 está fuera de rango (%4)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>it must be an absolute path</source>
        <translation>debe ser una ruta absoluta</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>it does not exist</source>
        <translation>no existe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>it is not a folder</source>
        <translation>no es una carpeta</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>it is not writable</source>
        <translation>no tiene permiso de escritura</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>it must be a single key</source>
        <translation>debe ser una sola tecla</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>it is not a key the panel can use</source>
        <translation>no es una tecla que el panel pueda usar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no Shift, Ctrl, Alt or Meta: Shift makes the step ten times bigger</source>
        <translation>sin Shift, Ctrl, Alt ni Meta: Shift multiplica el paso por diez</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the window uses it for %1</source>
        <translation>la ventana la usa para %1</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1: choose a key</source>
        <translation>%1: elegir una tecla</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: %2 cannot be used: %3</source>
        <translation>%1: no se puede usar %2: %3</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: %2 is already %3</source>
        <translation>%1: %2 ya se usa como %3</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1: %2: %3</source>
        <translation>%1: %2: %3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: %2 is not one of %3</source>
        <translation>%1: %2 no es ninguno de %3</translation>
    </message>
</context>
<context>
    <name>ProgramDock</name>
    <message>
        <location filename="../../app/window/docks/program_dock.py" line="+181"/>
        <source>program %1 refused: %2</source>
        <translation>programa %1 rechazado: %2</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>only programs of points (CSV, JSON) are saved as JSON</source>
        <translation>solo los programas de puntos (CSV, JSON) se guardan como JSON</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>program %1 cannot run: %2</source>
        <translation>el programa %1 no se puede ejecutar: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>program %1: %2 segments, nothing sent yet</source>
        <translation>programa %1: %2 segmentos, aún no se ha enviado nada</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>the program has no moves</source>
        <translation>el programa no tiene movimientos</translation>
    </message>
    <message>
        <location line="+93"/>
        <source>program saved to %1 (%2 points)</source>
        <translation>programa guardado en %1 (%2 puntos)</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>the program stopped: %1</source>
        <translation>el programa se detuvo: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>program %1 done: %2/%3 executed in %4 s</source>
        <translation>programa %1 terminado: %2/%3 ejecutados en %4 s</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>program %1 stopped: %2/%3 executed in %4 s</source>
        <translation>programa %1 detenido: %2/%3 ejecutados en %4 s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1; %2 frames, %3 retransmission(s)</source>
        <translation>%1; %2 tramas, %3 retransmisión(es)</translation>
    </message>
</context>
<context>
    <name>ProgramPanel</name>
    <message>
        <source>Programs (*.csv *.json);;All files (*)</source>
        <translation type="vanished">Programas (*.csv *.json);;Todos los archivos (*)</translation>
    </message>
    <message>
        <location filename="../../widgets/program_panel.py" line="+39"/>
        <source>no program loaded</source>
        <translation>ningún programa cargado</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation type="vanished">Cargar…</translation>
    </message>
    <message>
        <source>Load a program: CSV with x,y,z,speed (mm, mm/s) or JSON</source>
        <translation type="vanished">Cargar un programa: CSV con x,y,z,speed (mm, mm/s) o JSON</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Save…</source>
        <translation>Guardar…</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Save the loaded program as JSON (x, y, z, speed per point)</source>
        <translation>Guardar el programa cargado como JSON (x, y, z, speed por punto)</translation>
    </message>
    <message>
        <source>Run</source>
        <translation type="vanished">Ejecutar</translation>
    </message>
    <message>
        <source>Stream the program to the device, 7 moves a frame</source>
        <translation type="vanished">Enviar el programa al dispositivo en flujo continuo, 7 movimientos por trama</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="vanished">Pausa</translation>
    </message>
    <message>
        <source>Send nothing more until Resume (queued moves go on)</source>
        <translation type="vanished">No enviar nada más hasta Reanudar (los movimientos en cola continúan)</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="vanished">Detener</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>&amp;Load…</source>
        <translation>&amp;Cargar…</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&amp;Run</source>
        <translation>&amp;Ejecutar</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+366"/>
        <source>P&amp;ause</source>
        <translation>Pa&amp;usa</translation>
    </message>
    <message>
        <location line="-363"/>
        <source>&amp;Stop</source>
        <translation>&amp;Detener</translation>
    </message>
    <message>
        <source>Send nothing more and flush the device&apos;s queue (STOP)</source>
        <translation type="vanished">No enviar nada más y vaciar la cola del dispositivo (STOP)</translation>
    </message>
    <message>
        <location line="-55"/>
        <source>Programs (*.gcode *.nc *.ngc *.tap *.dxf *.svg *.csv *.json);;G-code (*.gcode *.nc *.ngc *.tap);;DXF drawings (*.dxf);;SVG drawings (*.svg);;Points (*.csv *.json);;All files (*)</source>
        <translation>Programas (*.gcode *.nc *.ngc *.tap *.dxf *.svg *.csv *.json);;G-code (*.gcode *.nc *.ngc *.tap);;Dibujos DXF (*.dxf);;Dibujos SVG (*.svg);;Puntos (*.csv *.json);;Todos los archivos (*)</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Load a program: G-code, DXF or SVG, or points (CSV with x,y,z,speed in mm and mm/s, or JSON)</source>
        <translation>Cargar un programa: G-code, DXF o SVG, o puntos (CSV con x,y,z,speed en mm y mm/s, o JSON)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Run the program on the device (checked against the box first)</source>
        <translation>Ejecutar el programa en el dispositivo (comprobado antes con la caja)</translation>
    </message>
    <message>
        <location line="+351"/>
        <source>Send nothing more until Resume (a device&apos;s queued moves go on)</source>
        <translation>No enviar nada más hasta Reanudar (los movimientos en cola del dispositivo continúan)</translation>
    </message>
    <message>
        <location line="-344"/>
        <source>Send nothing more and stop the device (its queue flushed)</source>
        <translation>No enviar nada más y detener el dispositivo (se vacía su cola)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Chord tolerance: how far the straight moves an arc or curve is cut into may stray from it</source>
        <translation>Tolerancia de cuerda: cuánto pueden apartarse de un arco o curva los movimientos rectos en que se divide</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Instructions executed by the device</source>
        <translation>Instrucciones ejecutadas por el dispositivo</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+137"/>
        <source>%v / %m executed</source>
        <translation>%v / %m ejecutadas</translation>
    </message>
    <message>
        <location line="-117"/>
        <source>The program&apos;s lines; the one under way is highlighted</source>
        <translation>Las líneas del programa; la que está en curso aparece resaltada</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The drawing&apos;s layers: the checked ones are run</source>
        <translation>Las capas del dibujo: se ejecutan las marcadas</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Program:</source>
        <translation>Programa:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Chord tolerance:</source>
        <translation>Tolerancia de cuerda:</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Load a program</source>
        <translation>Cargar un programa</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Save the program</source>
        <translation>Guardar el programa</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>JSON (*.json)</source>
        <translation>JSON (*.json)</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>reading %1…</source>
        <translation>leyendo %1…</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 (%2 lines)</source>
        <translation>%1 (%2 líneas)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (%2 entities)</source>
        <translation>%1 (%2 entidades)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (%2 elements)</source>
        <translation>%1 (%2 elementos)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2 points)</source>
        <translation>%1 (%2 puntos)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>no program</source>
        <translation>sin programa</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>line %1</source>
        <translation>línea %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>entity %1</source>
        <translation>entidad %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>element %1</source>
        <translation>elemento %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point %1</source>
        <translation>punto %1</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>length %1 mm (travel moves %2 mm), %3 segments</source>
        <translation>longitud %1 mm (movimientos en vacío %2 mm), %3 segmentos</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>box X %1 to %2, Y %3 to %4, Z %5 to %6 mm</source>
        <translation>caja X de %1 a %2, Y de %3 a %4, Z de %5 a %6 mm</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>about %1 (h:mm:ss) at %2 mm/s where the program sets no speed</source>
        <translation>aprox. %1 (h:mm:ss) a %2 mm/s donde el programa no fija velocidad</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>%1
Not for this program: %2</source>
        <translation>%1
No apto para este programa: %2</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>not connected to a device</source>
        <translation>no conectado a un dispositivo</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>motion is off</source>
        <translation>el movimiento está desactivado</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1
Refused: %2</source>
        <translation>%1
Rechazado: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1
Not now: %2</source>
        <translation>%1
Ahora no: %2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Send nothing more until Resume. This device has no feed hold: it goes on running the moves it already holds (the status line says how many, and when it stands still); Stop flushes them</source>
        <translation>No enviar nada más hasta Reanudar. Este dispositivo no tiene retención de avance: sigue ejecutando los movimientos que ya tiene (la línea de estado indica cuántos y cuándo se detiene); Detener los descarta</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Send nothing more until Resume. The move under way finishes, then the stage stands still (this device has no feed hold)</source>
        <translation>No enviar nada más hasta Reanudar. El movimiento en curso termina y después la platina se detiene (este dispositivo no tiene retención de avance)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Resume</source>
        <translation>Reanudar</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>, paused</source>
        <translation>, en pausa</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, about %1 s left</source>
        <translation>, quedan unos %1 s</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>sent %1, acknowledged %2, executed %3; %4 instructions/s%5; %6 retransmission(s)</source>
        <translation>enviadas %1, confirmadas %2, ejecutadas %3; %4 instrucciones/s%5; %6 retransmisión(es)</translation>
    </message>
</context>
<context>
    <name>RawConsole</name>
    <message>
        <location filename="../../app/window/console/display.py" line="+16"/>
        <source>text</source>
        <translation>texto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hex</source>
        <translation>hex</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mixed</source>
        <translation>mixto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>relative</source>
        <translation>relativo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>absolute</source>
        <translation>absoluto</translation>
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
        <translation>Texto (*.txt)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>All files (*)</source>
        <translation>Todos los archivos (*)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export traffic</source>
        <translation>Exportar tráfico</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>exported %1 line to %2</source>
        <translation>%1 línea exportada a %2</translation>
    </message>
    <message>
        <location filename="../../app/window/console/display.py" line="+26"/>
        <source>Bytes as text (\r \n \xNN escapes), hex (47 45 54), or mixed (text, &lt;0A&gt; for the rest)</source>
        <translation>Bytes como texto (escapes \r \n \xNN), hex (47 45 54) o mixto (texto, &lt;0A&gt; para el resto)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Times: seconds since the session start, wall-clock time, or the gap since the line above</source>
        <translation>Tiempos: segundos desde el inicio de la sesión, hora del reloj o intervalo desde la línea anterior</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Time</source>
        <translation>Tiempo</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Show the time column</source>
        <translation>Mostrar la columna de tiempo</translation>
    </message>
    <message>
        <location filename="../../app/window/console/filter_bar.py" line="+57"/>
        <source>TX</source>
        <translation>TX</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show what was sent to the device</source>
        <translation>Mostrar lo enviado al dispositivo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>RX</source>
        <translation>RX</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show what the device sent</source>
        <translation>Mostrar lo que envió el dispositivo</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Kinds</source>
        <translation>Tipos</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Which kinds of lines to show</source>
        <translation>Qué tipos de líneas mostrar</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Poll</source>
        <translation>Consulta</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Show the idle position queries and their replies (hidden by default; counted below)</source>
        <translation>Mostrar las consultas de posición en reposo y sus respuestas (ocultas por defecto; se cuentan abajo)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>filter (regex)</source>
        <translation>filtro (regex)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Show only lines matching this regular expression (case-insensitive) in their direction, kind, hex, text or meaning, e.g. error|FA00</source>
        <translation>Mostrar solo las líneas que coinciden con esta expresión regular (sin distinguir mayúsculas) en su dirección, tipo, hex, texto o significado, p. ej. error|FA00</translation>
    </message>
    <message>
        <location filename="../../app/window/console/traffic_console.py" line="+124"/>
        <source>paused</source>
        <translation>en pausa</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>New lines do not scroll the view: scroll to the bottom to follow</source>
        <translation>Las líneas nuevas no desplazan la vista: bajar hasta el final para seguirlas</translation>
    </message>
    <message>
        <location filename="../../app/window/console/filter_bar.py" line="+12"/>
        <source>search (regex)</source>
        <translation>buscar (regex)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Highlight matching lines; Enter or F3: next, Shift+F3: previous</source>
        <translation>Resaltar las líneas coincidentes; Enter o F3: siguiente, Shift+F3: anterior</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Previous match (Shift+F3)</source>
        <translation>Coincidencia anterior (Shift+F3)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Next match (F3)</source>
        <translation>Coincidencia siguiente (F3)</translation>
    </message>
    <message>
        <location filename="../../app/window/console/status.py" line="+45"/>
        <source>Lines in the session, shown, hidden polls, errors, matches</source>
        <translation>Líneas de la sesión, mostradas, consultas ocultas, errores, coincidencias</translation>
    </message>
    <message>
        <location filename="../../app/window/console/traffic_console.py" line="+18"/>
        <source>Export…</source>
        <translation>Exportar…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save the lines shown (filtered) as text or CSV</source>
        <translation>Guardar las líneas mostradas (filtradas) como texto o CSV</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Clear</source>
        <translation>Borrar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Forget the lines (the session log keeps them)</source>
        <translation>Olvidar las líneas (el registro de sesión las conserva)</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>TX (blue): sent to the device; RX (green): received; grey: notes and the device&apos;s own text; red: errors. Double-click a line to go to its request, reply or first copy.</source>
        <translation>TX (azul): enviado al dispositivo; RX (verde): recibido; gris: notas y texto propio del dispositivo; rojo: errores. Doble clic en una línea para ir a su petición, su respuesta o su primera copia.</translation>
    </message>
    <message>
        <location line="+102"/>
        <source>the console keeps the newest %1 lines: older lines are dropped from it as new ones come; the session log keeps every line</source>
        <translation>la consola conserva las %1 líneas más recientes: las más antiguas se descartan a medida que llegan otras nuevas; el registro de sesión conserva todas las líneas</translation>
    </message>
    <message>
        <location line="+133"/>
        <source>line %1 is no longer in the console (its line limit dropped it); the session log has it</source>
        <translation>la línea %1 ya no está en la consola (la descartó su límite de líneas); está en el registro de sesión</translation>
    </message>
    <message>
        <source>%1 lines reached the console&apos;s limit and were cleared; the session log keeps them</source>
        <translation type="vanished">%1 líneas alcanzaron el límite de la consola y se borraron; el registro de sesión las conserva</translation>
    </message>
    <message>
        <location filename="../../app/window/console/status.py" line="+16"/>
        <source>%1 line</source>
        <translation>%1 línea</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 lines</source>
        <translation>%1 líneas</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 shown</source>
        <translation>%1 mostradas</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 older in the session log</source>
        <translation>%1 más antiguas en el registro de sesión</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 poll hidden</source>
        <translation>%1 de consulta ocultas</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 error</source>
        <translation>%1 error</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 errors</source>
        <translation>%1 errores</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 match</source>
        <translation>%1 coincidencia</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 matches</source>
        <translation>%1 coincidencias</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 more hidden by the filters</source>
        <translation>%1 más ocultas por los filtros</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The console keeps the newest %1 lines (Settings): older lines are dropped from it, the session log on disk keeps every line</source>
        <translation>La consola conserva las %1 líneas más recientes (Ajustes): las más antiguas se descartan; el registro de sesión en disco conserva todas las líneas</translation>
    </message>
    <message>
        <location filename="../../app/window/console/traffic_console.py" line="+114"/>
        <source>export failed: %1</source>
        <translation>exportación fallida: %1</translation>
    </message>
    <message>
        <location filename="../../app/window/console/export.py" line="+2"/>
        <source>exported %1 lines to %2</source>
        <translation>%1 líneas exportadas a %2</translation>
    </message>
    <message>
        <location filename="../../app/window/console/table.py" line="+60"/>
        <source>motion</source>
        <translation>movimiento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>query</source>
        <translation>petición</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>poll</source>
        <translation>consulta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>setting</source>
        <translation>ajuste</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error</source>
        <translation>error</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>debug</source>
        <translation>depuración</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>note</source>
        <translation>nota</translation>
    </message>
</context>
<context>
    <name>SendLine</name>
    <message>
        <location filename="../../widgets/send_line.py" line="+19"/>
        <source>text</source>
        <translation>texto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hex</source>
        <translation>hex</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>text: UTF-8 with \r \n \t \0 \\ \xNN escapes, plus the line ending;
hex: bytes like 48 45 4C 4C 4F, sent as they are</source>
        <translation>texto: UTF-8 con los escapes \r \n \t \0 \\ \xNN, más el fin de línea;
hex: bytes como 48 45 4C 4C 4F, enviados tal cual</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Appended to every line sent in text mode</source>
        <translation>Se añade a cada línea enviada en modo texto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send</source>
        <translation>Enviar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Send the line to the device (Enter)</source>
        <translation>Enviar la línea al dispositivo (Enter)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Sen&amp;d:</source>
        <translation>E&amp;nviar:</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>hex bytes, e.g. 48 45 4C 4C 4F (Up/Down: history)</source>
        <translation>bytes hex, p. ej. 48 45 4C 4C 4F (Arriba/Abajo: historial)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>text to send (Up/Down: history)</source>
        <translation>texto a enviar (Arriba/Abajo: historial)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>nothing to send</source>
        <translation>nada que enviar</translation>
    </message>
</context>
<context>
    <name>SettingsDialog</name>
    <message>
        <location filename="../../widgets/settings_dialog.py" line="+78"/>
        <source>Settings</source>
        <translation>Ajustes</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Connection</source>
        <translation>Conexión</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Console &amp;&amp; log</source>
        <translation>Consola &amp;&amp; registro</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Display</source>
        <translation>Visualización</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Keyboard jog</source>
        <translation>Desplazamiento por teclado</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Appearance &amp;&amp; language</source>
        <translation>Apariencia &amp;&amp; idioma</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Use and save</source>
        <translation>Aplicar y guardar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Use and save, and keep this open</source>
        <translation>Aplicar y guardar, y mantener abierto</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Put every field back to its default (saved only with OK or Apply)</source>
        <translation>Devolver cada campo a su valor predeterminado (solo se guarda con Aceptar o Aplicar)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Close without saving</source>
        <translation>Cerrar sin guardar</translation>
    </message>
    <message>
        <location line="+103"/>
        <source>Position polling</source>
        <translation>Consulta de posición</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>How often the position is read while a move is being confirmed, in hertz (%1 to %2 Hz). Faster confirms the end of each jog step sooner; above 20 Hz nothing is seen sooner.</source>
        <translation>Frecuencia de lectura de la posición mientras se confirma un movimiento, en hercios (%1 a %2 Hz). Cuanto más rápida, antes se confirma el final de cada paso de desplazamiento; por encima de 20 Hz no se ve nada antes.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Poll while moving:</source>
        <translation>Consulta en movimiento:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Seconds between position reads while nothing moves (%1 to %2 s). This is also how a device that restarted or stopped answering is noticed.</source>
        <translation>Segundos entre lecturas de posición mientras nada se mueve (%1 a %2 s). Así también se detecta un dispositivo que se ha reiniciado o ha dejado de responder.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Poll when idle:</source>
        <translation>Consulta en reposo:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Console</source>
        <translation>Consola</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> lines</source>
        <translation> líneas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep every line</source>
        <translation>Conservar todas las líneas</translation>
    </message>
    <message>
        <source>The most lines the console keeps: 0 keeps every line (a spool file on disk and about 33 bytes a line in memory), else %1 to %2 lines. The session log keeps every byte either way.</source>
        <translation type="vanished">Máximo de líneas que conserva la consola: 0 conserva todas (un archivo de volcado en disco y unos 33 bytes por línea en memoria); si no, de %1 a %2 líneas. El registro de sesión conserva todos los bytes en cualquier caso.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The most lines the console keeps: 0 keeps every line (a spool file on disk and about 33 bytes a line in memory), else %1 to %2 lines, the oldest dropped as new ones come. The session log keeps every byte either way.</source>
        <translation>Máximo de líneas que conserva la consola: 0 conserva todas (un archivo de volcado en disco y unos 33 bytes por línea en memoria); si no, de %1 a %2 líneas, y las más antiguas se descartan a medida que llegan otras nuevas. El registro de sesión conserva todos los bytes en cualquier caso.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Console lines kept:</source>
        <translation>Líneas conservadas en consola:</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Session log</source>
        <translation>Registro de sesión</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write every byte of every session to a file</source>
        <translation>Escribir cada byte de cada sesión en un archivo</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>One file a session in the log folder; the oldest go beyond 200 MiB</source>
        <translation>Un archivo por sesión en la carpeta de registros; los más antiguos se borran al superar 200 MiB</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the app-data folder</source>
        <translation>la carpeta de datos de la aplicación</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Default: %1</source>
        <translation>Predeterminado: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>An absolute path to a folder you can write to; empty: the default folder</source>
        <translation>Ruta absoluta a una carpeta con permiso de escritura; vacío: la carpeta predeterminada</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Browse…</source>
        <translation>Examinar…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose the session log folder</source>
        <translation>Elegir la carpeta del registro de sesión</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Session log folder:</source>
        <translation>Carpeta del registro de sesión:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Positions</source>
        <translation>Posiciones</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Millimetres (mm)</source>
        <translation>Milímetros (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Inches (in)</source>
        <translation>Pulgadas (in)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The unit positions are shown in; the device is always sent millimetres</source>
        <translation>Unidad en que se muestran las posiciones; al dispositivo siempre se le envían milímetros</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Units shown:</source>
        <translation>Unidades mostradas:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> decimals</source>
        <translation> decimales</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>As the device resolves</source>
        <translation>Según la resolución del dispositivo</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Decimals of the positions shown (%1 to %2), or as many as the device resolves (0.01 mm: 2)</source>
        <translation>Decimales de las posiciones mostradas (%1 a %2), o tantos como resuelva el dispositivo (0.01 mm: 2)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Decimals shown:</source>
        <translation>Decimales mostrados:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Travel limits</source>
        <translation>Límites de recorrido</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clamp a move to the limits instead of refusing it</source>
        <translation>Ajustar un movimiento a los límites en lugar de rechazarlo</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>What a device starts with until its own limits are saved</source>
        <translation>Lo que usa un dispositivo hasta que se guarden sus propios límites</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Each device&apos;s box is set in Motion → Travel limits…</source>
        <translation>La caja de cada dispositivo se define en Movimiento → Límites de recorrido…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Jog keys</source>
        <translation>Teclas de desplazamiento</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>X-:</source>
        <translation>X-:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog X down by one step</source>
        <translation>Desplazar X un paso en sentido negativo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X+:</source>
        <translation>X+:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog X up by one step</source>
        <translation>Desplazar X un paso en sentido positivo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y-:</source>
        <translation>Y-:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog Y down by one step</source>
        <translation>Desplazar Y un paso en sentido negativo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y+:</source>
        <translation>Y+:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog Y up by one step</source>
        <translation>Desplazar Y un paso en sentido positivo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z-:</source>
        <translation>Z-:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog Z down by one step</source>
        <translation>Desplazar Z un paso en sentido negativo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z+:</source>
        <translation>Z+:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog Z up by one step</source>
        <translation>Desplazar Z un paso en sentido positivo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Smaller step:</source>
        <translation>Paso menor:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The next smaller step</source>
        <translation>El siguiente paso más pequeño</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Larger step:</source>
        <translation>Paso mayor:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The next larger step</source>
        <translation>El siguiente paso más grande</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Click, then press one key (no Shift, Ctrl, Alt or Meta)</source>
        <translation>Hacer clic y pulsar una tecla (sin Shift, Ctrl, Alt ni Meta)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Shift with a jog key makes the step ten times bigger. Esc (Stop), Tab, Enter, Space and F3 are the window&apos;s own.</source>
        <translation>Shift con una tecla de desplazamiento multiplica el paso por diez. Esc (Detener), Tab, Enter, Espacio y F3 están reservadas para la ventana.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Appearance and language</source>
        <translation>Apariencia e idioma</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+10"/>
        <source>As the system</source>
        <translation>Como el sistema</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>Light</source>
        <translation>Claro</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dark</source>
        <translation>Oscuro</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light or dark colours, or those of the desktop</source>
        <translation>Colores claros u oscuros, o los del escritorio</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Theme:</source>
        <translation>Tema:</translation>
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
        <translation>Idioma de la interfaz; --lang y $MOTIONPANEL_LANG tienen prioridad</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Language:</source>
        <translation>Idioma:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A new language shows when the panel next starts.</source>
        <translation>El nuevo idioma se aplicará la próxima vez que se inicie el panel.</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>%1: %2 is not a number from %3 to %4 %5</source>
        <translation>%1: %2 no es un número de %3 a %4 %5</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Memory grows with the session: about 33 MB a million lines.</source>
        <translation>La memoria crece con la sesión: unos 33 MB por millón de líneas.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>About %1 MB of memory at most.</source>
        <translation>Como máximo, unos %1 MB de memoria.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Session log folder</source>
        <translation>Carpeta del registro de sesión</translation>
    </message>
</context>
<context>
    <name>ShortcutsDialog</name>
    <message>
        <location filename="../../widgets/shortcuts_dialog.py" line="+75"/>
        <source>Keyboard Shortcuts</source>
        <translation>Atajos de teclado</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Search shortcuts…</source>
        <translation>Buscar atajos…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Search shortcuts</source>
        <translation>Buscar atajos</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Keys</source>
        <translation>Teclas</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Action</source>
        <translation>Acción</translation>
    </message>
    <message>
        <location line="+77"/>
        <source>No shortcut matches “%1”.</source>
        <translation>Ningún atajo coincide con “%1”.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No keyboard shortcuts.</source>
        <translation>No hay atajos de teclado.</translation>
    </message>
</context>
<context>
    <name>SpeedControl</name>
    <message>
        <location filename="../../widgets/speed_control.py" line="+53"/>
        <source>Speed:</source>
        <translation>Velocidad:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed of the next moves</source>
        <translation>Velocidad de los próximos movimientos</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Apply</source>
        <translation>Aplicar</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+45"/>
        <source>Send the speed in the field to the device</source>
        <translation>Enviar al dispositivo la velocidad del campo</translation>
    </message>
    <message>
        <location line="-40"/>
        <source>The speed the device reports (it may round)</source>
        <translation>La velocidad que indica el dispositivo (puede redondearla)</translation>
    </message>
    <message>
        <location line="+122"/>
        <source>Speed, %1 to %2 in/s; press Enter or Apply to send</source>
        <translation>Velocidad, de %1 a %2 in/s; pulsar Enter o Aplicar para enviar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag and release to send (%1 to %2 in/s)</source>
        <translation>Arrastrar y soltar para enviar (%1 a %2 in/s)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Speed, %1 to %2 mm/s; press Enter or Apply to send</source>
        <translation>Velocidad, de %1 a %2 mm/s; pulsar Enter o Aplicar para enviar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag and release to send (%1 to %2 mm/s)</source>
        <translation>Arrastrar y soltar para enviar (%1 a %2 mm/s)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>device: %1 in/s</source>
        <translation>dispositivo: %1 in/s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>device: %1 mm/s</source>
        <translation>dispositivo: %1 mm/s</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+3"/>
        <source>%1; nothing sent</source>
        <translation>%1; no se ha enviado nada</translation>
    </message>
</context>
<context>
    <name>StatusLine</name>
    <message>
        <location filename="../../widgets/status_line.py" line="+19"/>
        <source>Disconnected</source>
        <translation>Desconectado</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No device is connected</source>
        <translation>No hay ningún dispositivo conectado</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+47"/>
        <source>Connecting…</source>
        <translation>Conectando…</translation>
    </message>
    <message>
        <location line="-45"/>
        <source>Opening the port and asking the device who it is</source>
        <translation>Abriendo el puerto y preguntando al dispositivo su identidad</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Idle</source>
        <translation>En reposo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Connected and not moving</source>
        <translation>Conectado y sin movimiento</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Moving</source>
        <translation>En movimiento</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A move is under way</source>
        <translation>Hay un movimiento en curso</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Busy</source>
        <translation>Ocupado</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A command is under way</source>
        <translation>Hay un comando en curso</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Paused</source>
        <translation>En pausa</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A program is paused: nothing more of it is sent until Resume</source>
        <translation>Hay un programa en pausa: no se envía nada más de él hasta Reanudar</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Error</source>
        <translation>Error</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The last command failed, or the connection did</source>
        <translation>Falló el último comando, o la conexión</translation>
    </message>
</context>
<context>
    <name>ThemeMenu</name>
    <message>
        <location filename="../../app/window/theme.py" line="+373"/>
        <source>&amp;Theme</source>
        <translation>&amp;Tema</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Follow the &amp;system</source>
        <translation>Seguir el &amp;sistema</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Light</source>
        <translation>&amp;Claro</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Dark</source>
        <translation>&amp;Oscuro</translation>
    </message>
</context>
<context>
    <name>TrafficFormat</name>
    <message>
        <location filename="../../widgets/traffic_format.py" line="+38"/>
        <source>\x needs two hex digits at column %1: %2</source>
        <translation>\x necesita dos dígitos hex en la columna %1: %2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>a lone backslash ends the line: write \\ for a backslash</source>
        <translation>una barra invertida sola termina la línea: escribir \\ para una barra invertida</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>unknown escape \%1 at column %2 (use \r \n \t \0 \\ \xNN)</source>
        <translation>escape desconocido \%1 en la columna %2 (usar \r \n \t \0 \\ \xNN)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>not hex: %1</source>
        <translation>no es hex: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>odd number of hex digits in %1: write 0%2 or pairs</source>
        <translation>número impar de dígitos hex en %1: escribir 0%2 o pares</translation>
    </message>
</context>
<context>
    <name>TrafficModel</name>
    <message>
        <location filename="../../app/window/console/table.py" line="-21"/>
        <source>Line</source>
        <translation>Línea</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time</source>
        <translation>Tiempo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dir</source>
        <translation>Dir</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bytes</source>
        <translation>Bytes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Meaning</source>
        <translation>Significado</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reply</source>
        <translation>Respuesta</translation>
    </message>
    <message>
        <location line="+316"/>
        <source>line %1: %2</source>
        <translation>línea %1: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>hex: %1</source>
        <translation>hex: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>text: %1</source>
        <translation>texto: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 (double-click to go there)</source>
        <translation>%1 (doble clic para ir allí)</translation>
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
        <translation>Seguir</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Keep the latest %1 s in view; zooming or panning stops it</source>
        <translation>Mantener a la vista los últimos %1 s; hacer zoom o mover la vista lo desactiva</translation>
    </message>
    <message>
        <location filename="../../widgets/timeline/plots.py" line="+32"/>
        <source>Bytes per second each way, in one-second bins: TX (blue) sent to the device, RX (green) received. Click a bin to show its first line in the console.</source>
        <translation>Bytes por segundo en cada sentido, en intervalos de un segundo: TX (azul) enviado al dispositivo, RX (verde) recibido. Hacer clic en un intervalo para mostrar su primera línea en la consola.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>rate</source>
        <translation>tasa</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Bytes per second</source>
        <translation>Bytes por segundo</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Command latency</source>
        <translation>Latencia de comandos</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Time from a request to its reply, in ms: one point per answered request (drawn as dots when few are in view). Click a point to show its line in the console.</source>
        <translation>Tiempo entre una petición y su respuesta, en ms: un punto por petición respondida (dibujados como marcadores cuando hay pocos a la vista). Hacer clic en un punto para mostrar su línea en la consola.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>latency</source>
        <translation>latencia</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>time since the session started</source>
        <translation>tiempo desde el inicio de la sesión</translation>
    </message>
</context>
<context>
    <name>TravelLimitsDialog</name>
    <message>
        <location filename="../../widgets/travel_limits_dialog.py" line="+19"/>
        <source>Travel limits</source>
        <translation>Límites de recorrido</translation>
    </message>
    <message>
        <source>Where the stage may go on %1. A jog, go-to or command-line move that would leave the box is refused before anything is sent, or clamped to its edge.</source>
        <translation type="vanished">Zona por la que puede moverse la platina en %1. Un desplazamiento, un Ir a o un movimiento desde la línea de comandos que saldría de la caja se rechaza antes de enviar nada, o se ajusta a su borde.</translation>
    </message>
    <message>
        <source>Limit moves to this box</source>
        <translation type="vanished">Limitar los movimientos a esta caja</translation>
    </message>
    <message>
        <source>min</source>
        <translation type="vanished">mín</translation>
    </message>
    <message>
        <source>max</source>
        <translation type="vanished">máx</translation>
    </message>
    <message>
        <source>%1:</source>
        <comment>an axis field&apos;s label</comment>
        <translation type="vanished">%1:</translation>
    </message>
    <message>
        <source>%1 min</source>
        <comment>an axis&apos; lower travel limit</comment>
        <translation type="vanished">%1 mín</translation>
    </message>
    <message>
        <source>%1 max</source>
        <comment>an axis&apos; upper travel limit</comment>
        <translation type="vanished">%1 máx</translation>
    </message>
    <message>
        <source>Refuse a move that would leave the box</source>
        <translation type="vanished">Rechazar un movimiento que saldría de la caja</translation>
    </message>
    <message>
        <source>Clamp it: go as far as the edge, and say so</source>
        <translation type="vanished">Ajustarlo: ir hasta el borde e indicarlo</translation>
    </message>
    <message>
        <source>%1: the minimum must be below the maximum</source>
        <translation type="vanished">%1: el mínimo debe ser menor que el máximo</translation>
    </message>
</context>
<context>
    <name>TravelLimitsForm</name>
    <message>
        <location filename="../../widgets/travel_limits_form.py" line="+45"/>
        <source>Limit moves to this box</source>
        <translation>Limitar los movimientos a esta caja</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>min</source>
        <translation>mín</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max</source>
        <translation>máx</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1:</source>
        <comment>an axis field&apos;s label</comment>
        <translation>%1:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 min</source>
        <comment>an axis&apos; lower travel limit</comment>
        <translation>%1 mín</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 max</source>
        <comment>an axis&apos; upper travel limit</comment>
        <translation>%1 máx</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Refuse a move that would leave the box</source>
        <translation>Rechazar un movimiento que saldría de la caja</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Clamp it: go as far as the edge, and say so</source>
        <translation>Ajustarlo: ir hasta el borde e indicarlo</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Where the stage may go on %1. A jog, go-to or command-line move that would leave the box is refused before anything is sent, or clamped to its edge.</source>
        <translation>Zona por la que puede moverse la platina en %1. Un desplazamiento, un Ir a o un movimiento desde la línea de comandos que saldría de la caja se rechaza antes de enviar nada, o se ajusta a su borde.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Connect a device to set where its stage may go.</source>
        <translation>Conecte un dispositivo para fijar por dónde puede moverse su platina.</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>%1: the minimum must be below the maximum</source>
        <translation>%1: el mínimo debe ser menor que el máximo</translation>
    </message>
</context>
<context>
    <name>TravelLimitsPanel</name>
    <message>
        <location line="+25"/>
        <source>Apply</source>
        <translation>Aplicar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Use these limits for this device from now on (kept for it)</source>
        <translation>Usar estos límites para este dispositivo a partir de ahora (se guardan para él)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Revert</source>
        <translation>Revertir</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Show the limits in use again</source>
        <translation>Volver a mostrar los límites en uso</translation>
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
        <translation>%1: edición cancelada, valor sin cambios</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 is an output. %2</source>
        <translation>%1 es una salida. %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1 = %2, not yet written to the device</source>
        <translation>%1 = %2, aún no escrito en el dispositivo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1. Warning: %2</source>
        <translation>%1. Aviso: %2</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1: %2 (Enter keeps it, Escape cancels)</source>
        <translation>%1: %2 (Enter lo conserva, Esc cancela)</translation>
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
        <translation>XY y tiempo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The path in 3D</source>
        <translation>La trayectoria en 3D</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The path seen from above and X, Y, Z against time</source>
        <translation>La trayectoria vista desde arriba y X, Y, Z en función del tiempo</translation>
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
        <translation>A&amp;justes…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Poll rates, console, log folder, units, jog keys, theme</source>
        <translation>Frecuencias de consulta, consola, carpeta de registros, unidades, teclas de desplazamiento, tema</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Help</source>
        <translation>A&amp;yuda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Keyboard shortcuts</source>
        <translation>Atajos de &amp;teclado</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;About Motion Panel</source>
        <translation>&amp;Acerca de Motion Panel</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>Jog X - / +</source>
        <translation>Desplazar X - / +</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jog Y - / +</source>
        <translation>Desplazar Y - / +</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jog Z - / +</source>
        <translation>Desplazar Z - / +</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shift + a jog key</source>
        <translation>Shift + una tecla de desplazamiento</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog ten times the step</source>
        <translation>Desplazar diez veces el paso</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hold a jog key</source>
        <translation>mantener una tecla de desplazamiento</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Keep jogging until it is released</source>
        <translation>Seguir desplazando hasta soltarla</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Keys: %1/%2 X, %3/%4 Y, %5/%6 Z, Shift ×10</source>
        <translation>Teclas: %1/%2 X, %3/%4 Y, %5/%6 Z, Shift ×10</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>, %1/%2 step</source>
        <translation>, %1/%2 paso</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>settings saved; the language from the next start</source>
        <translation>ajustes guardados; el idioma se aplica en el próximo inicio</translation>
    </message>
    <message>
        <source>the session log from the next start</source>
        <translation type="vanished">el registro de sesión se aplica en el próximo inicio</translation>
    </message>
    <message>
        <source>the language from the next start</source>
        <translation type="vanished">el idioma se aplica en el próximo inicio</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>settings saved</source>
        <translation>ajustes guardados</translation>
    </message>
    <message>
        <source>settings saved; %1</source>
        <translation type="vanished">ajustes guardados; %1</translation>
    </message>
</context>
<context>
    <name>WorkFrame</name>
    <message>
        <location filename="../../app/window/docks/work_frame.py" line="+59"/>
        <source>work coordinates: %1</source>
        <translation>coordenadas de trabajo: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>work zero not set: the position is unknown</source>
        <translation>cero de pieza no fijado: la posición es desconocida</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>work zero set at %1 %2 (machine)</source>
        <translation>cero de pieza fijado en %1 %2 (máquina)</translation>
    </message>
    <message>
        <source>work zero set at %1 mm (machine)</source>
        <translation type="vanished">cero de pieza fijado en %1 mm (máquina)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>work zero cleared: work coordinates are machine coordinates</source>
        <translation>cero de pieza borrado: las coordenadas de trabajo son las de máquina</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>work zero kept in place: %1</source>
        <translation>cero de pieza mantenido: %1</translation>
    </message>
</context>
<context>
    <name>messages</name>
    <message>
        <location filename="message_templates.py" line="+15"/>
        <source>to ({x:g}, {y:g}, {z:g}) mm</source>
        <translation>hacia ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>to its target</source>
        <translation>hacia su destino</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: COXIRIS has no stop command; the device finishes the move under way {target} (a blocking sketch answers nothing until then) and then carries out what it had already received; motionctl sent nothing more</source>
        <translation>interrumpido: COXIRIS no tiene comando de parada; el dispositivo termina el movimiento en curso {target} (un sketch bloqueante no responde nada hasta entonces) y después ejecuta lo que ya había recibido; motionctl no envió nada más</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: Visiomex has no stop command; the device carries out the move packet it was sent {target} (FP0001, its steps, then FA0001); motionctl sent nothing more</source>
        <translation>interrumpido: Visiomex no tiene comando de parada; el dispositivo ejecuta el paquete de movimiento que se le envió {target} (FP0001, sus pasos y luego FA0001); motionctl no envió nada más</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: pi-frame has no stop command and sends no replies; the device carries out the frame it was sent {target}; motionctl sent nothing more</source>
        <translation>interrumpido: pi-frame no tiene comando de parada y no envía respuestas; el dispositivo ejecuta la trama que se le envió {target}; motionctl no envió nada más</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: Firmata has no stop command; the board finishes the step message under way (at most 16383 steps) and stops there; the move&apos;s later messages, if it had more, were not sent</source>
        <translation>interrumpido: Firmata no tiene comando de parada; la placa termina el mensaje de pasos en curso (como máximo 16383 pasos) y se detiene ahí; los mensajes posteriores del movimiento, si los tenía, no se enviaron</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: {protocol} has no stop command; the device finishes what it was sent; motionctl sent nothing more</source>
        <translation>interrumpido: {protocol} no tiene comando de parada; el dispositivo termina lo que se le envió; motionctl no envió nada más</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted before the device was talked to: nothing was sent</source>
        <translation>interrumpido antes de comunicarse con el dispositivo: no se envió nada</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: {command} does not move the stage</source>
        <translation>interrumpido: {command} no mueve la platina</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted before the move was sent: the stage does not move</source>
        <translation>interrumpido antes de enviar el movimiento: la platina no se mueve</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted again while stopping: the {protocol} stop may not have arrived; the device may still be moving</source>
        <translation>interrumpido de nuevo durante la parada: puede que la parada de {protocol} no haya llegado; puede que el dispositivo aún se esté moviendo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: the {protocol} stop was sent but not acknowledged ({error}); the device may still be moving</source>
        <translation>interrumpido: la parada de {protocol} se envió pero no se confirmó ({error}); puede que el dispositivo aún se esté moviendo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted again</source>
        <translation>interrumpido de nuevo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: stopped (the {protocol} stop was acknowledged; its queue is flushed); where the stage stopped could not be read: {error}</source>
        <translation>interrumpido: detenido (la parada de {protocol} se confirmó; su cola está vaciada); no se pudo leer dónde se detuvo la platina: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: stopped at ({x:g}, {y:g}, {z:g}) mm (the {protocol} stop was acknowledged; its queue is flushed)</source>
        <translation>interrumpido: detenido en ({x:g}, {y:g}, {z:g}) mm (la parada de {protocol} se confirmó; su cola está vaciada)</translation>
    </message>
    <message>
        <location line="-17"/>
        <source>usage: {usage} (got {count} arguments)</source>
        <translation>uso: {usage} (se recibieron {count} argumentos)</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>--force is for raw only</source>
        <translation>--force solo sirve para raw</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command} needs --port (the device to talk to)</source>
        <translation>{command} necesita --port (el dispositivo con el que comunicarse)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command} needs --protocol ({choices})</source>
        <translation>{command} necesita --protocol ({choices})</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>usage: {usage}</source>
        <translation>uso: {usage}</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>--kind {kind} refused: --kind is for jog only (move is in mm)</source>
        <translation>--kind {kind} rechazado: --kind solo sirve para jog (move va en mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>usage: {command} {axes} ({protocol} has {count} axes)</source>
        <translation>uso: {command} {axes} ({protocol} tiene {count} ejes)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>--kind {kind} refused: {protocol} moves are {kinds}</source>
        <translation>--kind {kind} rechazado: los movimientos de {protocol} son {kinds}</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>speed {speed:g} mm/s refused: the device allows {low:g} to {high:g} mm/s</source>
        <translation>velocidad de {speed:g} mm/s rechazada: el dispositivo admite de {low:g} a {high:g} mm/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed {speed:g} mm/s refused ({error})</source>
        <translation>velocidad de {speed:g} mm/s rechazada ({error})</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>raw move to ({x:g}, {y:g}, {z:g}) mm</source>
        <translation>movimiento en bruto hacia ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <source>{file} names no protocol (no connection note: a motionctl --log file or a spy:// capture has none): give --protocol</source>
        <translation type="vanished">{file} no indica ningún protocolo (sin nota de conexión: un archivo de motionctl --log o una captura spy:// no la tienen): indicar --protocol</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>{file}: its connection note: {error}</source>
        <translation>{file}: su nota de conexión: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>its connection notes name {named}</source>
        <translation>sus notas de conexión indican {named}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>try another --protocol</source>
        <translation>probar con otro --protocol</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nothing in {file} decodes as {protocol} ({count} records of traffic, none a {protocol} frame); {hint}</source>
        <translation>nada en {file} se decodifica como {protocol} ({count} entradas de tráfico, ninguna es una trama de {protocol}); {hint}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SVG scale {value:g} refused: it must be above 0</source>
        <translation>se rechaza la escala SVG {value:g}: debe ser mayor que 0</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>macro {name} ({count} step)</source>
        <translation>macro {name} ({count} paso)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name} ({count} steps)</source>
        <translation>macro {name} ({count} pasos)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a macro needs a name</source>
        <translation>una macro necesita un nombre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro name {name!r}… is over {limit} characters</source>
        <translation>el nombre de macro {name!r}… supera los {limit} caracteres</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro name {name!r} holds a control character</source>
        <translation>el nombre de macro {name!r} contiene un carácter de control</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name} is for {protocol}, not {device}</source>
        <translation>la macro {name} es para {protocol}, no para {device}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name} has no steps</source>
        <translation>la macro {name} no tiene pasos</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name} has {count} steps; at most {limit}</source>
        <translation>la macro {name} tiene {count} pasos; como máximo {limit}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name}, step {number} ({step!r}): {error}</source>
        <translation>macro {name}, paso {number} ({step!r}): {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the step is over {limit} characters</source>
        <translation>el paso supera los {limit} caracteres</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a step is one line (use one step per line)</source>
        <translation>un paso es una sola línea (usar un paso por línea)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the step is empty</source>
        <translation>el paso está vacío</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown command {command!r}; a step is one of: {commands}</source>
        <translation>comando desconocido {command!r}; un paso es uno de: {commands}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command} is a {owner} command</source>
        <translation>{command} es un comando de {owner}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>usage: wait SECONDS</source>
        <translation>uso: wait SEGUNDOS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wait {seconds:g} s refused: from 0 to {limit:g} s</source>
        <translation>wait {seconds:g} s rechazado: de 0 a {limit:g} s</translation>
    </message>
    <message>
        <source>{name} stopped before step {number} ({step})</source>
        <translation type="vanished">{name} se detuvo antes del paso {number} ({step})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name} stopped before step {number} ({step})</source>
        <translation>macro {name} detenida antes del paso {number} ({step})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name} stopped during step {number}</source>
        <translation>macro {name} detenida durante el paso {number}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: not a Motion Panel macro file (no &quot;format&quot;: &quot;{format}&quot;)</source>
        <translation>{where}: no es un archivo de macros de Motion Panel (falta &quot;format&quot;: &quot;{format}&quot;)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: macro file version {version!r}; this reads {reads}</source>
        <translation>{where}: versión de archivo de macros {version!r}; este panel lee {reads}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: &quot;macros&quot; is not a list</source>
        <translation>{where}: &quot;macros&quot; no es una lista</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {count} macros; at most {limit}</source>
        <translation>{where}: {count} macros; como máximo {limit}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: macro {number}</source>
        <translation>{where}: macro {number}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: two {protocol} macros are named {name!r}</source>
        <translation>{where}: dos macros de {protocol} se llaman {name!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where} is not an object with name, protocol and steps</source>
        <translation>{where} no es un objeto con nombre, protocolo y pasos</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where} has no name</source>
        <translation>{where} no tiene nombre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where} ({name!r}): unknown protocol {protocol!r}</source>
        <translation>{where} ({name!r}): protocolo desconocido {protocol!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where} ({name!r}): &quot;steps&quot; is not a list of strings</source>
        <translation>{where} ({name!r}): &quot;steps&quot; no es una lista de cadenas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where} ({name!r}): over {limit} steps or a step too long</source>
        <translation>{where} ({name!r}): más de {limit} pasos o un paso demasiado largo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro file</source>
        <translation>archivo de macros</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{path}: not JSON ({error})</source>
        <translation>{path}: no es JSON ({error})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} is not a JSON number</source>
        <translation>{name} no es un número JSON</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>saved macros</source>
        <translation>macros guardadas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>it cannot be read</source>
        <translation>no se puede leer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>it is not an INI file Qt can read</source>
        <translation>no es un archivo INI que Qt pueda leer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>settings file</source>
        <translation>archivo de ajustes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot read the settings file {file}: {why}</source>
        <translation>no se puede leer el archivo de ajustes {file}: {why}</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>{url} ({protocol}, {baud} baud)</source>
        <translation>{url} ({protocol}, {baud} baudios)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{error}; waiting for {url}</source>
        <translation>{error}; esperando a {url}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the saved setup was refused: {error}</source>
        <translation>se rechazó la configuración guardada: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{identity} on {url}</source>
        <translation>{identity} en {url}</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>{line} not changed: not connected</source>
        <translation>{line} sin cambiar: no conectado</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no break sent: not connected</source>
        <translation>break no enviado: no conectado</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>the position went from ({position}) to (0, 0, 0) mm while nothing was sent: the device restarted</source>
        <translation>la posición pasó de ({position}) a (0, 0, 0) mm sin que se enviara nada: el dispositivo se reinició</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>{error}; not sent: {jobs}; talking to it again</source>
        <translation>{error}; sin enviar: {jobs}; reconectando</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>{error}; talking to it again</source>
        <translation>{error}; reconectando</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not sent: the device is being reconnected</source>
        <translation>sin enviar: el dispositivo se está reconectando</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>stopped before it was sent</source>
        <translation>detenido antes de enviarse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the connection was lost</source>
        <translation>se perdió la conexión</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>abandoned: disconnected while it was under way</source>
        <translation>abandonado: se desconectó mientras estaba en curso</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>relative move by ({dx:g}, {dy:g}, {dz:g}) {unit}</source>
        <translation>movimiento relativo de ({dx:g}, {dy:g}, {dz:g}) {unit}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown job {job!r}</source>
        <translation>tarea desconocida {job!r}</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>{hint} ({error})</source>
        <translation>{hint} ({error})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{error}; not sent: {jobs}</source>
        <translation>{error}; sin enviar: {jobs}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{error}; connecting again when {url} is back</source>
        <translation>{error}; se reconectará cuando {url} vuelva a estar disponible</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{url} is back: connecting again</source>
        <translation>{url} vuelve a estar disponible: reconectando</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device says: {text}</source>
        <translation>el dispositivo dice: {text}</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the bridge to {device} is closed</source>
        <translation>el puente a {device} está cerrado</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot create a pseudo-terminal for {device}: {error}</source>
        <translation>no se puede crear un pseudoterminal para {device}: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bridge is not open</source>
        <translation>el puente no está abierto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device on {device} failed: {error}</source>
        <translation>el dispositivo en {device} falló: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device on {device} went away: {error}</source>
        <translation>el dispositivo en {device} desapareció: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device on {device} went away (its port was closed)</source>
        <translation>el dispositivo en {device} desapareció (se cerró su puerto)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the pseudo-terminal {path} failed: {error}</source>
        <translation>el pseudoterminal {path} falló: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>writing to the device on {device} failed: {error}</source>
        <translation>falló la escritura en el dispositivo en {device}: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>writing to the pseudo-terminal {path} failed: {error}</source>
        <translation>falló la escritura en el pseudoterminal {path}: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>abandoned: the connection is closing</source>
        <translation>abandonado: la conexión se está cerrando</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{error}; still full after {seconds:.0f} s</source>
        <translation>{error}; la cola sigue llena tras {seconds:.0f} s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command} failed after {tries} tries; the last: {error}</source>
        <translation>{command} falló tras {tries} intentos; el último: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device restarted during {command} ({event}): its position and settings are lost</source>
        <translation>el dispositivo se reinició durante {command} ({event}): se han perdido su posición y sus ajustes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device restarted ({event}): its position and settings are lost</source>
        <translation>el dispositivo se reinició ({event}): se han perdido su posición y sus ajustes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device did not finish its reply to {command} within {seconds:.3g} s</source>
        <translation>el dispositivo no terminó su respuesta a {command} en {seconds:.3g} s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device did not answer to {command} within {seconds:.3g} s</source>
        <translation>el dispositivo no respondió a {command} en {seconds:.3g} s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{message}; it sent {count} unexpected frame(s), the last: {frame}</source>
        <translation>{message}; envió {count} trama(s) inesperada(s), la última: {frame}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{message} (it may still be moving: {protocol} answers nothing until a blocking move has ended; try again once it has stopped)</source>
        <translation>{message} (puede que aún se esté moviendo: {protocol} no responde nada hasta que termina un movimiento bloqueante; volver a intentarlo cuando se haya detenido)</translation>
    </message>
    <message>
        <location line="+87"/>
        <source>no modem control lines</source>
        <translation>sin líneas de control de módem</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{dtr}, {rts}, {cts}, {dsr}, {cd}, {ri}</source>
        <translation>{dtr}, {rts}, {cts}, {dsr}, {cd}, {ri}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{line} ?</source>
        <translation>{line} ?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{line} on</source>
        <translation>{line} activa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{line} off</source>
        <translation>{line} inactiva</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>unreadable: {error}</source>
        <translation>ilegible: {error}</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>error {code}: {message}</source>
        <translation>error {code}: {message}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error: {message}</source>
        <translation>error: {message}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position unknown (({x:g}, {y:g}, {z:g}) mm counted from where the session began; Home or Set Home to know it)</source>
        <translation>posición desconocida (({x:g}, {y:g}, {z:g}) mm contados desde donde empezó la sesión; usar Origen o Fijar origen para conocerla)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position ({x:g}, {y:g}, {z:g}) mm</source>
        <translation>posición ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position ({x:g}, {y:g}, {z:g}) mm (commanded, confirmed)</source>
        <translation>posición ({x:g}, {y:g}, {z:g}) mm (ordenada, confirmada)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position ({x:g}, {y:g}, {z:g}) mm (commanded)</source>
        <translation>posición ({x:g}, {y:g}, {z:g}) mm (ordenada)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>feedback {code} ({meaning})</source>
        <translation>realimentación {code} ({meaning})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>feedback {code} {bytes}</source>
        <translation>realimentación {code} {bytes}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>feedback {code}</source>
        <translation>realimentación {code}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the line {text!r}</source>
        <translation>la línea {text!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an unreadable frame ({reason}): {bytes}</source>
        <translation>una trama ilegible ({reason}): {bytes}</translation>
    </message>
    <message>
        <location line="-95"/>
        <source>a directory</source>
        <translation>un directorio</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a named pipe (FIFO)</source>
        <translation>una tubería con nombre (FIFO)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a character device</source>
        <translation>un dispositivo de caracteres</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a block device</source>
        <translation>un dispositivo de bloques</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a socket</source>
        <translation>un socket</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot read the {what} {file}: {why}</source>
        <translation>no se puede leer el {what} {file}: {why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{kind}, not a regular file</source>
        <translation>{kind}, no un archivo normal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a special file</source>
        <translation>un archivo especial</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: larger than {limit} ({size:,} bytes), too large for a {what}</source>
        <translation>{file}: más de {limit} ({size:,} bytes), demasiado grande para un {what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: larger than {limit}, too large for a {what}</source>
        <translation>{file}: más de {limit}, demasiado grande para un {what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: not UTF-8 text (line {line}), not a {what}</source>
        <translation>{file}: no es texto UTF-8 (línea {line}), no es un {what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: a NUL byte (line {line}), not a {what}</source>
        <translation>{file}: un byte NUL (línea {line}), no es un {what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file} line {line}: longer than {limit:,} characters, not a {what} line</source>
        <translation>{file} línea {line}: más de {limit:,} caracteres, no es una línea de {what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a frame body is {expected} bytes, not {length}</source>
        <translation>el cuerpo de una trama tiene {expected} bytes, no {length}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>flag byte {byte:#04x}, expected 0xf0</source>
        <translation>byte de indicador {byte:#04x}, se esperaba 0xf0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>checksum {got:#04x}, expected {expected:#04x}</source>
        <translation>suma de comprobación {got:#04x}, se esperaba {expected:#04x}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0x90 followed by {byte:#04x} inside the data</source>
        <translation>0x90 seguido de {byte:#04x} dentro de los datos</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no tail within {most} bytes</source>
        <translation>sin cola de trama en {most} bytes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a SysEx message needs at least a command byte</source>
        <translation>un mensaje SysEx necesita al menos un byte de comando</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SysEx data must be 7-bit; got {byte:#04x}</source>
        <translation>los datos SysEx deben ser de 7 bits; se recibió {byte:#04x}</translation>
    </message>
    <message>
        <location line="+356"/>
        <source>{source} names no protocol: decoded as {protocol}, which its traffic reads as ({frames} frames recognised)</source>
        <translation>{source} no indica ningún protocolo: decodificado como {protocol}, el protocolo que revela su tráfico ({frames} tramas reconocidas)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {number}: not a traffic log line: {line!r}</source>
        <translation>{source} línea {number}: no es una línea de registro de tráfico: {line!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no traffic in it (not a Motion Panel log)</source>
        <translation>{source}: no contiene tráfico (no es un registro de Motion Panel)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>traffic log</source>
        <translation>registro de tráfico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: not a Motion Panel log nor a pyserial spy:// capture: line {number} is not a traffic log line: {line!r}; for spy://, {hint}</source>
        <translation>{file}: no es un registro de Motion Panel ni una captura spy:// de pyserial: la línea {number} no es una línea de registro de tráfico: {line!r}; para spy://, {hint}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: empty, not a Motion Panel log nor a pyserial spy:// capture (spy&apos;s raw format leaves its file empty); {hint}</source>
        <translation>{file}: vacío, no es un registro de Motion Panel ni una captura spy:// de pyserial (el formato raw de spy deja su archivo vacío); {hint}</translation>
    </message>
    <message>
        <location line="-446"/>
        <source>the device reported: {reported}</source>
        <translation>el dispositivo informó: {reported}</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>{protocol} device</source>
        <translation>dispositivo {protocol}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device did not report a position (it answered {value})</source>
        <translation>el dispositivo no informó de una posición (respondió {value})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device is at ({x:g}, {y:g}, {z:g}) mm, not where its last move ended: its replies are no longer taken as arrival</source>
        <translation>el dispositivo está en ({x:g}, {y:g}, {z:g}) mm, no donde terminó su último movimiento: sus respuestas ya no se toman como llegada</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>{protocol} has no speed limits to report</source>
        <translation>{protocol} no tiene límites de velocidad que indicar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed {speed:g} refused: the speed must be a positive number</source>
        <translation>velocidad de {speed:g} rechazada: la velocidad debe ser un número positivo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed {speed:g} {unit} refused: the device allows {low:g} to {high:g} {unit}</source>
        <translation>velocidad de {speed:g} {unit} rechazada: el dispositivo admite de {low:g} a {high:g} {unit}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed {speed:g} {unit} written, but this firmware times its steps from its step delays (15, 16) alone: moves go at {real:.3f} {unit}</source>
        <translation>velocidad de {speed:g} {unit} escrita, pero este firmware temporiza sus pasos solo a partir de sus retardos entre pasos (15, 16): los movimientos van a {real:.3f} {unit}</translation>
    </message>
    <message>
        <location line="-36"/>
        <source>move to ({x:g}, {y:g}, {z:g}) mm</source>
        <translation>movimiento a ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>jog by ({dx:g}, {dy:g}, {dz:g}) {unit}</source>
        <translation>desplazamiento de ({dx:g}, {dy:g}, {dz:g}) {unit}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no way to go home</source>
        <translation>{protocol} no tiene forma de ir al origen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>go home</source>
        <translation>retorno al origen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no set-home command</source>
        <translation>{protocol} no tiene comando para fijar el origen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what} refused: home is outside the travel limits</source>
        <translation>{what} rechazado: el origen está fuera de los límites de recorrido</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no arc moves</source>
        <translation>{protocol} no admite movimientos en arco</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>arc</source>
        <translation>arco</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no dwell</source>
        <translation>{protocol} no admite esperas</translation>
    </message>
    <message>
        <location line="-19"/>
        <source>stopped at ({x:g}, {y:g}, {z:g}) mm</source>
        <translation>detenido en ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the move to {target} did not end within {seconds:.1f} s</source>
        <translation>el movimiento a {target} no terminó en {seconds:.1f} s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no protocol to read them with</source>
        <translation>no hay ningún protocolo con el que interpretarlos</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>program point {number}</source>
        <translation>punto {number} del programa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw bytes refused: {protocol} cannot read them as a command ({reason}), so they cannot be checked against the travel limits ({box}); send them with force to send them anyway</source>
        <translation>bytes en bruto rechazados: {protocol} no puede interpretarlos como un comando ({reason}), así que no se pueden comprobar con los límites de recorrido ({box}); usar force para enviarlos de todos modos</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw bytes refused: they hold {count} commands, {moves} of them moves; send a move alone, so that it is checked and followed to its end</source>
        <translation>bytes en bruto rechazados: contienen {count} comandos, {moves} de ellos movimientos; enviar un movimiento solo, para que se compruebe y se siga hasta su final</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw move {command}</source>
        <translation>movimiento en bruto {command}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what}: not a move the panel can check</source>
        <translation>{what}: no es un movimiento que el panel pueda comprobar</translation>
    </message>
    <message>
        <location line="+214"/>
        <source>{what} {text!r} is not a number the device accepts: use digits with an optional sign and one decimal point, e.g. -12.5</source>
        <translation>{what} {text!r} no es un número que acepte el dispositivo: usar dígitos con un signo opcional y un punto decimal, p. ej. -12.5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what} {value!r} is not a finite number</source>
        <translation>{what} {value!r} no es un número finito</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what} {value:g} is out of range: the device handles at most ±{limit:g}</source>
        <translation>{what} {value:g} está fuera de rango: el dispositivo admite como máximo ±{limit:g}</translation>
    </message>
    <message>
        <location line="-203"/>
        <source>{source}: not a parameter profile: {error}</source>
        <translation>{source}: no es un perfil de parámetros: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: not a parameter profile: a number too long</source>
        <translation>{source}: no es un perfil de parámetros: un número demasiado largo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: not a parameter profile: nested too deeply</source>
        <translation>{source}: no es un perfil de parámetros: anidamiento demasiado profundo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: protocol must be a name in quotes</source>
        <translation>{source}: protocol debe ser un nombre entre comillas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: a profile for {named!r}, not for {protocol!r}</source>
        <translation>{source}: un perfil para {named!r}, no para {protocol!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} (line {line}): unknown key {key!r}</source>
        <translation>{source} (línea {line}): clave desconocida {key!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: unknown key {key!r}</source>
        <translation>{source}: clave desconocida {key!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no [parameters] table with values in it</source>
        <translation>{source}: no hay ninguna tabla [parameters] con valores</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {line}</source>
        <translation>{source} línea {line}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: unknown parameter {name!r} for {protocol}</source>
        <translation>{where}: parámetro desconocido {name!r} para {protocol}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {error}</source>
        <translation>{where}: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {name}: not a number the device takes ({range})</source>
        <translation>{where}: {name}: no es un número que admita el dispositivo ({range})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: only firmware outputs ({names}), which a profile does not write</source>
        <translation>{source}: solo salidas del firmware ({names}), que un perfil no escribe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>profile</source>
        <translation>perfil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot write the profile {path}: {error}</source>
        <translation>no se puede escribir el perfil {path}: {error}</translation>
    </message>
    <message>
        <location line="+190"/>
        <source>{low} to {high} in steps of {step}</source>
        <translation>de {low} a {high} en pasos de {step}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{low} to {high} (whole numbers)</source>
        <translation>de {low} a {high} (números enteros)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{low} to {high}</source>
        <translation>de {low} a {high}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: {value!r} is not a number ({range})</source>
        <translation>{name}: {value!r} no es un número ({range})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: {value} refused: {range}</source>
        <translation>{name}: {value} rechazado: {range}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: {value} refused: the device takes {range}</source>
        <translation>{name}: {value} rechazado: el dispositivo admite {range}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>this protocol has no parameters</source>
        <translation>este protocolo no tiene parámetros</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown parameter {name!r} (did you mean {close}?): use a name or an id 1..{count}; &apos;motionctl ... param list&apos; lists them</source>
        <translation>parámetro desconocido {name!r} (¿quería decir {close}?): usar un nombre o un id 1..{count}; &apos;motionctl ... param list&apos; los enumera</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown parameter {name!r}: use a name or an id 1..{count}; &apos;motionctl ... param list&apos; lists them</source>
        <translation>parámetro desconocido {name!r}: usar un nombre o un id 1..{count}; &apos;motionctl ... param list&apos; los enumera</translation>
    </message>
    <message>
        <location line="-197"/>
        <source>its frames carry absolute targets, so a relative move needs the position: Set Home where the stage stands, Home, or move to an absolute point first (in the panel, or motionctl set-home, home or move X Y Z)</source>
        <translation>sus tramas llevan destinos absolutos, así que un movimiento relativo necesita la posición: usar primero Fijar origen donde está la platina, Origen, o mover a un punto absoluto (en el panel, o motionctl set-home, home o move X Y Z)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Home or Set Home (in the panel, or motionctl home / set-home) to start counting</source>
        <translation>usar Origen o Fijar origen (en el panel, o motionctl home / set-home) para empezar a contar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Set Home where the stage stands (in the panel, or motionctl set-home) to start counting; with no home move of its own, Home needs a count too</source>
        <translation>usar Fijar origen donde está la platina (en el panel, o motionctl set-home) para empezar a contar; como no tiene búsqueda de origen propia, Origen también necesita un conteo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command} refused: position unknown: {protocol} cannot be asked where it is and no commanded position is kept for this port; {how}</source>
        <translation>{command} rechazado: posición desconocida: no se puede preguntar a {protocol} dónde está y no hay ninguna posición ordenada guardada para este puerto; {how}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command} refused: position unknown: {protocol} cannot be asked where it is and no position is counted for this port; {how}</source>
        <translation>{command} rechazado: posición desconocida: no se puede preguntar a {protocol} dónde está y no hay ninguna posición contada para este puerto; {how}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position unknown: {protocol} cannot be asked where it is and no commanded position is kept for this port; {how}</source>
        <translation>posición desconocida: no se puede preguntar a {protocol} dónde está y no hay ninguna posición ordenada guardada para este puerto; {how}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position unknown: {protocol} cannot be asked where it is and no position is counted for this port; {how}</source>
        <translation>posición desconocida: no se puede preguntar a {protocol} dónde está y no hay ninguna posición contada para este puerto; {how}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>this firmware reads the digits as µm whatever the type letter ({kind} is not read): the stage moves X {x:.3f} mm, Y {y:.3f} mm</source>
        <translation>este firmware lee los dígitos como µm sea cual sea la letra de tipo ({kind} no se lee): la platina se mueve X {x:.3f} mm, Y {y:.3f} mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no identity query: the device cannot be asked what it is</source>
        <translation>{protocol} no tiene consulta de identidad: no se puede preguntar al dispositivo qué es</translation>
    </message>
    <message>
        <location line="+367"/>
        <source>{where}: {name} {value!r} is not a number</source>
        <translation>{where}: {name} {value!r} no es un número</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {name} is not a finite float32 number</source>
        <translation>{where}: {name} no es un número float32 finito</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>{where}: {name} {value!r} is not a finite float32 number</source>
        <translation>{where}: {name} {value!r} no es un número float32 finito</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>{where}: speed {speed:g} mm/s must be above 0</source>
        <translation>{where}: la velocidad {speed:g} mm/s debe ser mayor que 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {line}: not CSV: {error}</source>
        <translation>{source} línea {line}: no es CSV: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {line}: the header must name x, y, z and speed (got nothing)</source>
        <translation>{source} línea {line}: la cabecera debe nombrar x, y, z y speed (no se recibió nada)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {line}: the header must name x, y, z and speed (got {columns})</source>
        <translation>{source} línea {line}: la cabecera debe nombrar x, y, z y speed (se recibió {columns})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {line}: {count} values, expected 4</source>
        <translation>{source} línea {line}: {count} valores, se esperaban 4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no header line (x,y,z,speed)</source>
        <translation>{source}: sin línea de cabecera (x,y,z,speed)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no points</source>
        <translation>{source}: sin puntos</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {line}: not JSON ({reason})</source>
        <translation>{source} línea {line}: no es JSON ({reason})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: not JSON the panel reads (a number too long)</source>
        <translation>{source}: no es un JSON que el panel pueda leer (un número demasiado largo)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: not JSON the panel reads (nested too deeply)</source>
        <translation>{source}: no es un JSON que el panel pueda leer (anidamiento demasiado profundo)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no &quot;points&quot; list</source>
        <translation>{source}: no hay lista &quot;points&quot;</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: expected [x, y, z, speed]</source>
        <translation>{where}: se esperaba [x, y, z, speed]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} point {number}</source>
        <translation>{source} punto {number}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: more than {count} points</source>
        <translation>{source}: más de {count} puntos</translation>
    </message>
    <message>
        <location line="-45"/>
        <source>program</source>
        <translation>programa</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>cannot write the program {path}: {error}</source>
        <translation>no se puede escribir el programa {path}: {error}</translation>
    </message>
    <message>
        <location line="-173"/>
        <source>this looks like a {found} controller, not {expected}</source>
        <translation>parece un controlador {found}, no {expected}</translation>
    </message>
    <message>
        <location line="-369"/>
        <source>--device names a device of a bench: give --bench FILE</source>
        <translation>--device nombra un dispositivo de un banco: indique --bench ARCHIVO</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>--port and --bench both name the device: give one of them</source>
        <translation>--port y --bench nombran ambos el dispositivo: indique solo uno</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{bench} has {count} devices: choose one with --device ({names})</source>
        <translation>{bench} tiene {count} dispositivos: elija uno con --device ({names})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{bench} has no device {name!r} (it has {names})</source>
        <translation>{bench} no tiene el dispositivo {name!r} (tiene {names})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>--protocol {typed} disagrees with the bench: {name} is {protocol}</source>
        <translation>--protocol {typed} no coincide con el banco: {name} es {protocol}</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>{what} {text!r} refused: a whole number is needed</source>
        <translation>{what} {text!r} rechazado: se necesita un número entero</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>radius {radius:g} mm refused: it must be above 0</source>
        <translation>radio de {radius:g} mm rechazado: debe ser mayor que 0</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;{command}&apos; is a {owner} command, not {protocol}&apos;s</source>
        <translation>«{command}» es una orden de {owner}, no de {protocol}</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>{axis} {value:g} mm refused: outside {low:g}..{high:g} mm (travel limits)</source>
        <translation>{axis} {value:g} mm rechazado: fuera de {low:g}..{high:g} mm (límites de recorrido)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the stage is not connected: connect it first</source>
        <translation>la platina no está conectada: conéctela primero</translation>
    </message>
    <message>
        <location line="+136"/>
        <source>{setting} {value} refused: {minimum:g} to {maximum:g} {unit}</source>
        <translation>{setting} {value} rechazado: de {minimum:g} a {maximum:g} {unit}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no setting {name!r}</source>
        <translation>{protocol} no tiene el ajuste {name!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no wire variants (got {name!r})</source>
        <translation>{protocol} no tiene variantes de transmisión (se recibió {name!r})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no variant {name!r} (variants: {known})</source>
        <translation>{protocol} no tiene la variante {name!r} (variantes: {known})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} moves are linear only (got {kind!r})</source>
        <translation>{protocol} solo admite movimientos lineales (se recibió {kind!r})</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>{protocol} cannot read sent frames</source>
        <translation>{protocol} no puede interpretar las tramas enviadas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the last {count} bytes are not a whole frame: the device would wait for the rest</source>
        <translation>los últimos {count} bytes no forman una trama completa: el dispositivo esperaría el resto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no whole frame in {count} bytes</source>
        <translation>ninguna trama completa en {count} bytes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} coordinate</source>
        <translation>coordenada {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} distance</source>
        <translation>distancia {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed</source>
        <translation>velocidad</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a coordinate</source>
        <translation>una coordenada</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the speed</source>
        <translation>la velocidad</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed {speed:g} mm/s refused: the speed must be positive</source>
        <translation>velocidad {speed:g} mm/s rechazada: la velocidad debe ser positiva</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw command refused: COXIRIS takes ASCII text only</source>
        <translation>comando en bruto rechazado: COXIRIS solo acepta texto ASCII</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw command refused: one line at a time (it contains a line break)</source>
        <translation>comando en bruto rechazado: una línea cada vez (contiene un salto de línea)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw command refused: it is empty, and the device ignores blank lines</source>
        <translation>comando en bruto rechazado: está vacío y el dispositivo ignora las líneas en blanco</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>COXIRIS has no command for {command}</source>
        <translation>COXIRIS no tiene comando para {command}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>command refused: {length} characters, the device takes at most {most} ({start}...)</source>
        <translation>comando rechazado: {length} caracteres, el dispositivo acepta como máximo {most} ({start}...)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device reported {what} as {text!r}, which is not a number</source>
        <translation>el dispositivo informó de {what} con el valor {text!r}, que no es un número</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device reported {what} as {text!r}</source>
        <translation>el dispositivo informó de {what} con el valor {text!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device does not know the command {name!r}</source>
        <translation>el dispositivo no conoce el comando {name!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device refused the command: {error}</source>
        <translation>el dispositivo rechazó el comando: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>expected DONE {command}, got {event}</source>
        <translation>se esperaba DONE {command}, se recibió {event}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position reply {data!r} does not hold three numbers</source>
        <translation>la respuesta de posición {data!r} no contiene tres números</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speeds are reported rounded to whole mm/s</source>
        <translation>las velocidades se indican redondeadas a mm/s enteros</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>positions are reported to 0.01 mm</source>
        <translation>las posiciones se indican con una resolución de 0.01 mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>non-ASCII bytes in a COXIRIS line: {bytes}</source>
        <translation>bytes no ASCII en una línea COXIRIS: {bytes}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>line refused: {length} characters, the device takes at most {most}</source>
        <translation>línea rechazada: {length} caracteres, el dispositivo acepta como máximo {most}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{line!r} has no line end: the device would wait for the rest</source>
        <translation>{line!r} no tiene fin de línea: el dispositivo esperaría el resto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an empty line: the device ignores it</source>
        <translation>una línea vacía: el dispositivo la ignora</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>non-ASCII bytes: COXIRIS takes ASCII text only</source>
        <translation>bytes no ASCII: COXIRIS solo acepta texto ASCII</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} {params!r} is not three numbers as the firmware reads them</source>
        <translation>{name} {params!r} no son tres números tal como los lee el firmware</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Motor steps per turn</source>
        <translation>Pasos del motor por vuelta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Motor steps per millimetre</source>
        <translation>Pasos del motor por milímetro</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Motor control pin {pin} (-1: none)</source>
        <translation>Pin {pin} de control del motor (-1: ninguno)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moves back to 0 by a relative move: the board has no homing</source>
        <translation>Vuelve a 0 con un movimiento relativo: la placa no tiene búsqueda de origen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no completion message: moves are estimated from speed and steps</source>
        <translation>sin mensaje de fin: los movimientos se estiman a partir de la velocidad y los pasos</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the version and firmware name (is a Firmata board on this port?)</source>
        <translation>la petición de versión y nombre del firmware (¿hay una placa Firmata en este puerto?)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed (rpm)</source>
        <translation>velocidad (rpm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>steps per revolution</source>
        <translation>pasos por revolución</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pin</source>
        <translation>pin</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>steps</source>
        <translation>pasos</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>capability response</source>
        <translation>respuesta de capacidades</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>analog mapping</source>
        <translation>mapa de pines analógicos</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>version request</source>
        <translation>petición de versión</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>firmware name request</source>
        <translation>petición de nombre del firmware</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>STEPPER_LIBRARY_VERSION request</source>
        <translation>petición STEPPER_LIBRARY_VERSION</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what} {value} refused: the stepper takes {low} to {high}</source>
        <translation>no se admite {what} = {value}: el motor paso a paso acepta de {low} a {high}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the board answered: {error}</source>
        <translation>la placa respondió: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{distance:g} mm refused: the motor moves in steps of {step:g} mm ({per_mm:g} steps/mm)</source>
        <translation>{distance:g} mm rechazados: el motor se mueve en pasos de {step:g} mm ({per_mm:g} pasos/mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the Firmata stepper is one axis (X): Y and Z must be 0</source>
        <translation>el motor paso a paso Firmata tiene un solo eje (X): Y y Z deben ser 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{count} pins refused: a stepper has 2 or 4 pins</source>
        <translation>{count} pines rechazados: un motor paso a paso tiene 2 o 4 pines</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmata has no message for {command}</source>
        <translation>Firmata no tiene mensaje para {command}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an empty Firmata message</source>
        <translation>un mensaje Firmata vacío</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmata protocol {major}.{minor}</source>
        <translation>protocolo Firmata {major}.{minor}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>analog pin {pin}: {value}</source>
        <translation>pin analógico {pin}: {value}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>digital port {port}: {bits:08b}</source>
        <translation>puerto digital {port}: {bits:08b}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>message {bytes}</source>
        <translation>mensaje {bytes}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SysEx {command:#04x}</source>
        <translation>SysEx {command:#04x}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>STEPPER_CONFIGURE {steps} steps/rev, pins {pins}</source>
        <translation>STEPPER_CONFIGURE {steps} pasos/rev, pines {pins}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>STEPPER_STEP {rpm} rpm, {steps} steps forward</source>
        <translation>STEPPER_STEP {rpm} rpm, {steps} pasos hacia delante</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>STEPPER_STEP {rpm} rpm, {steps} steps reverse</source>
        <translation>STEPPER_STEP {rpm} rpm, {steps} pasos hacia atrás</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a STEPPER_STEP of {count} data bytes, not 6</source>
        <translation>un STEPPER_STEP de {count} bytes de datos, no 6</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>framing</source>
        <translation>trama incorrecta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>checksum</source>
        <translation>suma de comprobación</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown command</source>
        <translation>comando desconocido</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bad arguments</source>
        <translation>argumentos incorrectos</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>queue full</source>
        <translation>cola llena</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>undocumented</source>
        <translation>no documentado</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error {code} ({meaning}) for {command}</source>
        <translation>error {code} ({meaning}) en {command}</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>speed {speed:g} mm/s refused: it must be above 0</source>
        <translation>velocidad {speed:g} mm/s rechazada: debe ser mayor que 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the position reply holds {count} numbers, not 3</source>
        <translation>la respuesta de posición contiene {count} números, no 3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the status reply holds {count} numbers, not 2</source>
        <translation>la respuesta de estado contiene {count} números, no 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>undocumented code {code}</source>
        <translation>código no documentado {code}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command}: the device answered error {code} ({meaning})</source>
        <translation>{command}: el dispositivo respondió con el error {code} ({meaning})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>moves are queued on the device; the position is read back while they run</source>
        <translation>los movimientos se encolan en el dispositivo; la posición se relee mientras se ejecutan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The next queued frame&apos;s number (0: random)</source>
        <translation>Número de la siguiente trama en cola (0: aleatorio)</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>dwell {ms} ms refused: the field is an int16 (0 to 32767)</source>
        <translation>espera de {ms} ms rechazada: el campo es un int16 (de 0 a 32767)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a queued frame holds 1 to {most} queued instructions</source>
        <translation>una trama en cola contiene de 1 a {most} instrucciones en cola</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the laser link has no instruction for {command}</source>
        <translation>el enlace láser no tiene instrucción para {command}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MOVE_LINEAR with {count} float values, not x, y, z and speed</source>
        <translation>MOVE_LINEAR con {count} valores float, no x, y, z y velocidad</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>word {word:#04x}</source>
        <translation>palabra {word:#04x}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>frame {number} ({words} ×{count})</source>
        <translation>trama {number} ({words} ×{count})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>frame {number} ({words})</source>
        <translation>trama {number} ({words})</translation>
    </message>
    <message>
        <location line="-28"/>
        <source>a field holds 1 to 255 values, not {count}</source>
        <translation>un campo contiene de 1 a 255 valores, no {count}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{value!r} is not one ASCII character</source>
        <translation>{value!r} no es un único carácter ASCII</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{value} does not fit a float32</source>
        <translation>{value} no cabe en un float32</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{value} does not fit a {kind} ({low} to {high})</source>
        <translation>{value} no cabe en un {kind} (de {low} a {high})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>command word {word:#04x} is outside 0x01..0x7F</source>
        <translation>la palabra de comando {word:#04x} está fuera de 0x01..0x7F</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>byte {index}: {byte:#04x} where a command word was expected</source>
        <translation>byte {index}: {byte:#04x} donde se esperaba una palabra de comando</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>byte {index}: a {kind} field without its count</source>
        <translation>byte {index}: un campo {kind} sin su recuento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>byte {index}: {count} {kind} values run past the data</source>
        <translation>byte {index}: {count} valores {kind} sobrepasan el final de los datos</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Encoder ticks per millimetre</source>
        <translation>Cuentas del encoder por milímetro</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moves back to (0, 0, 0) with a Linear frame: the device has no homing</source>
        <translation>Vuelve a (0, 0, 0) con una trama Linear: el dispositivo no tiene búsqueda de origen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write-only: positions are commanded, completion estimated from distance and speed</source>
        <translation>solo escritura: las posiciones son ordenadas y el final se estima a partir de la distancia y la velocidad</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed {axis}</source>
        <translation>velocidad {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>centre {axis}</source>
        <translation>centro {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>radius</source>
        <translation>radio</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>angular speed</source>
        <translation>velocidad angular</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dwell</source>
        <translation>espera</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{field} {value:g} {unit} refused: a pi-frame field holds {low} to {high}</source>
        <translation>no se admite {field} = {value:g} {unit}: un campo pi-frame admite de {low} a {high}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{field} {distance:g} mm refused: the device moves in ticks of {tick:g} mm ({per_mm:g} ticks/mm)</source>
        <translation>no se admite {field} = {distance:g} mm: el dispositivo se mueve en cuentas de {tick:g} mm ({per_mm:g} cuentas/mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{field} {distance:g} mm refused: {ticks} ticks do not fit 16 bits ({low:g} to {high:g} mm at {per_mm:g} ticks/mm)</source>
        <translation>no se admite {field} = {distance:g} mm: {ticks} cuentas no caben en 16 bits (de {low:g} a {high:g} mm con {per_mm:g} cuentas/mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pi-frame has no frame for {command}</source>
        <translation>pi-frame no tiene trama para {command}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a {length}-byte frame</source>
        <translation>una trama de {length} bytes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Linear X={x} Y={y} Z={z} ticks at {sx}/{sy}/{sz} ticks/s</source>
        <translation>Linear X={x} Y={y} Z={z} cuentas a {sx}/{sy}/{sz} cuentas/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Circular centre ({x}, {y}) radius {radius} ticks, {start:g}° to {end:g}° {turn} at {speed:g}°/s, Z to {z}</source>
        <translation>Circular centro ({x}, {y}) radio {radius} cuentas, de {start:g}° a {end:g}° {turn} a {speed:g}°/s, Z a {z}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dwell {ms} ms</source>
        <translation>Dwell {ms} ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>action {number}</source>
        <translation>acción {number}</translation>
    </message>
    <message>
        <location line="+81"/>
        <source>move package confirmed</source>
        <translation>paquete de movimiento confirmado</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>action accomplished</source>
        <translation>acción completada</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>package size mismatch</source>
        <translation>tamaño de paquete incorrecto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid command type</source>
        <translation>tipo de comando no válido</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid motion type</source>
        <translation>tipo de movimiento no válido</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid direction for the X axis</source>
        <translation>dirección no válida para el eje X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid direction for the Y axis</source>
        <translation>dirección no válida para el eje Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid set parameter ID</source>
        <translation>ID de parámetro no válido al fijar un parámetro</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>parse function error in the firmware</source>
        <translation>error en la función de análisis del firmware</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid driving mechanism</source>
        <translation>mecanismo de accionamiento no válido</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an error code the documentation does not list</source>
        <translation>un código de error que la documentación no recoge</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{parameter} set</source>
        <translation>{parameter} fijado</translation>
    </message>
    <message>
        <source>Sets input_speed_steady_x and _y (parameters 21 and 22). This firmware revision times its steps from step_delay_instantaneous (15, 16) only, so moves keep their pace.</source>
        <translation type="vanished">Fija input_speed_steady_x e _y (parámetros 21 y 22). Esta revisión del firmware temporiza sus pasos solo a partir de step_delay_instantaneous (15, 16), así que los movimientos mantienen su ritmo.</translation>
    </message>
    <message>
        <location line="-45"/>
        <source>Visiomex has no homing at this revision: Home moves back to (0, 0) by a relative move from the position the panel counted</source>
        <translation>Visiomex no tiene búsqueda de origen en esta revisión: Origen vuelve a (0, 0) con un movimiento relativo desde la posición que ha contado el panel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no read-back: the panel keeps what was last written</source>
        <translation>sin relectura: el panel guarda lo último que se escribió</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>positions are commanded, and confirmed by FA0001 when the move ends</source>
        <translation>las posiciones son ordenadas y se confirman con FA0001 al terminar el movimiento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a reply comes 1 s after a packet: the firmware waits for 1 s of silence</source>
        <translation>la respuesta llega 1 s después de un paquete: el firmware espera 1 s de silencio</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>parameter {number} set</source>
        <translation>parámetro {number} fijado</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>feedback code {code} is not documented</source>
        <translation>el código de respuesta {code} no está documentado</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command}: the device answered {code} ({meaning}); this firmware revision runs the move anyway</source>
        <translation>{command}: el dispositivo respondió {code} ({meaning}); esta revisión del firmware ejecuta el movimiento de todos modos</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command}: the device answered {code} ({meaning})</source>
        <translation>{command}: el dispositivo respondió {code} ({meaning})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command}: expected {wanted}, got {code}</source>
        <translation>{command}: se esperaba {wanted}, se recibió {code}</translation>
    </message>
    <message>
        <location line="-46"/>
        <source>18-character packets at 9600 baud, as the seed documents</source>
        <translation>paquetes de 18 caracteres a 9600 baudios, según la documentación original (seed)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the seed&apos;s packets; feedback lines start with &apos;&gt;&apos;</source>
        <translation>los paquetes de seed; las líneas de respuesta empiezan por &apos;&gt;&apos;</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>12-character packets at 115200 baud, moves in mm, D goes home</source>
        <translation>paquetes de 12 caracteres a 115200 baudios, movimientos en mm, D va al origen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Visiomex moves are relative: the panel sends the distance to go</source>
        <translation>Visiomex solo hace movimientos relativos: el panel envía la distancia a recorrer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the speed is parameters 21 and 22: it is sent as two sets</source>
        <translation>la velocidad son los parámetros 21 y 22: se envía con dos escrituras</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Visiomex has no packet for {command}</source>
        <translation>Visiomex no tiene paquete para {command}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>move kind {kind!r} refused: Visiomex moves are {kinds}</source>
        <translation>tipo de movimiento {kind!r} rechazado: los movimientos de Visiomex son {kinds}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z {distance:g} mm refused: the Visiomex controller has X and Y only</source>
        <translation>Z {distance:g} mm rechazado: el controlador Visiomex solo tiene X e Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} {value:g} {unit} refused: this device moves in 1 µm</source>
        <translation>{axis} {value:g} {unit} rechazado: este dispositivo se mueve en pasos de 1 µm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} {value:g} {unit} refused: this device moves in whole {unit}</source>
        <translation>{axis} {value:g} {unit} rechazado: este dispositivo se mueve en {unit} enteros</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} {value:g} {unit} refused: one move goes at most {most} {unit} per axis ({digits} digits)</source>
        <translation>{axis} {value:g} {unit} rechazado: un movimiento llega como máximo a {most} {unit} por eje ({digits} dígitos)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>packet refused: Visiomex takes ASCII characters only</source>
        <translation>paquete rechazado: Visiomex solo acepta caracteres ASCII</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>packet refused: it is empty</source>
        <translation>paquete rechazado: está vacío</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>packet refused: {length} characters, a Visiomex packet has {most} (a line ending counts too)</source>
        <translation>paquete rechazado: {length} caracteres, un paquete Visiomex tiene {most} (el fin de línea también cuenta)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>non-ASCII bytes in a Visiomex line: {bytes}</source>
        <translation>bytes no ASCII en una línea Visiomex: {bytes}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>that packet gets no reply: send it from the console instead</source>
        <translation>ese paquete no recibe respuesta: enviarlo desde la consola</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>packet {packet}</source>
        <translation>paquete {packet}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set {parameter} = {value}</source>
        <translation>fijar {parameter} = {value}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>move linear X {x} Y {y}</source>
        <translation>movimiento lineal X {x} Y {y}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>move rotational X {x} Y {y}</source>
        <translation>movimiento rotacional X {x} Y {y}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>move steps X {x} Y {y}</source>
        <translation>movimiento en pasos X {x} Y {y}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>move {kind} X {x} Y {y}</source>
        <translation>movimiento {kind} X {x} Y {y}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>packet {packet!r}</source>
        <translation>paquete {packet!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>move packet {packet!r} is not as the protocol documents</source>
        <translation>el paquete de movimiento {packet!r} no es como lo documenta el protocolo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{packet} (set {parameter})</source>
        <translation>{packet} (fijar {parameter})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the firmware forces driving_mechanism to 1 after every set</source>
        <translation>el firmware impone driving_mechanism = 1 tras cada escritura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the firmware recomputes {parameter} after every set: this value will not stay (it holds {held:g})</source>
        <translation>el firmware recalcula {parameter} tras cada escritura: este valor no se mantendrá (tiene {held:g})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the firmware recomputes {parameter} at every move: this value will not stay</source>
        <translation>el firmware recalcula {parameter} en cada movimiento: este valor no se mantendrá</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>this firmware revision reads {parameter} only at boot: moves do not change until the device restarts</source>
        <translation>esta revisión del firmware solo lee {parameter} al arrancar: los movimientos no cambian hasta que el dispositivo se reinicie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>this firmware revision never reads {parameter}: moves do not change</source>
        <translation>esta revisión del firmware nunca lee {parameter}: los movimientos no cambian</translation>
    </message>
    <message>
        <location line="-75"/>
        <source>Steps per move</source>
        <translation>Pasos por movimiento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X: 1 mm = {x1}, 10 mm = {x10} · Y: 1 mm = {y1}, 10 mm = {y10} (truncated: the firmware counts in 32-bit floats)</source>
        <translation>X: 1 mm = {x1}, 10 mm = {x10} · Y: 1 mm = {y1}, 10 mm = {y10} (truncados: el firmware cuenta con floats de 32 bits)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{steps} steps, {stepping} s of stepping; FA0001 about {total} s after the packet</source>
        <translation>{steps} pasos, {stepping} s dando pasos; FA0001 unos {total} s después del paquete</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{text}; after a move in which Y stepped, {later} s (X&apos;s low phase is Y&apos;s last delay, {delay} µs: the ramps do not restore the delays)</source>
        <translation>{text}; tras un movimiento en el que Y dio pasos, {later} s (la fase baja de X es el último retardo de Y, {delay} µs: las rampas no restauran los retardos)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A 10 mm X move</source>
        <translation>Un movimiento de 10 mm en X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no: the firmware&apos;s Y loop runs the ramp count (R_y = 0 with these values), not the {asked} steps a 10 mm move asks for; set 22 and 24 so that the ramp length is above 0 (e.g. 22 = 6000, 24 = 1)</source>
        <translation>no: el bucle Y del firmware ejecuta el recuento de rampa (R_y = 0 con estos valores), no los {asked} pasos que pide un movimiento de 10 mm; fijar 22 y 24 de modo que la longitud de rampa sea mayor que 0 (p. ej. 22 = 6000, 24 = 1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{runs} of the {asked} steps of a 10 mm Y move, {seconds} s: the firmware&apos;s Y loop runs the ramp count R_y (at most the ramp length {ramp}), not the distance, and speeds up without slowing down</source>
        <translation>{runs} de los {asked} pasos de un movimiento de 10 mm en Y, {seconds} s: el bucle Y del firmware ejecuta el recuento de rampa R_y (como máximo la longitud de rampa {ramp}), no la distancia, y acelera sin decelerar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y moves</source>
        <translation>Movimiento en Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none: the ramp length is 0 on both axes (it follows 21 ÷ 23 and 13 - 11); every X step takes 15 high plus 16 low</source>
        <translation>ninguna: la longitud de rampa es 0 en ambos ejes (depende de 21 ÷ 23 y 13 - 11); cada paso de X dura 15 en alto más 16 en bajo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X over {x} steps, Y over {y} steps, between 13/14 (slow) and 11/12 (fast)</source>
        <translation>X en {x} pasos, Y en {y} pasos, entre 13/14 (lento) y 11/12 (rápido)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ramps</source>
        <translation>Rampas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not used</source>
        <translation>No usados</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{names}: the values in the table differ from power-on, but this firmware does not use them</source>
        <translation>{names}: los valores de la tabla difieren de los de encendido, pero este firmware no los usa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Overwritten after every set</source>
        <translation>Sobrescritos tras cada escritura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{ids}: the firmware recomputes them; a written value does not stay</source>
        <translation>{ids}: el firmware los recalcula; un valor escrito no se mantiene</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Overwritten at every move</source>
        <translation>Sobrescritos en cada movimiento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{ids}: the ramp counts of the last move</source>
        <translation>{ids}: los recuentos de rampa del último movimiento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Never read</source>
        <translation>Nunca leídos</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{ids}: writing them changes nothing (27 is forced to 1 after every set)</source>
        <translation>{ids}: escribirlos no cambia nada (a 27 se le impone 1 tras cada escritura)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read only at boot</source>
        <translation>Leídos solo al arrancar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{ids}: the cycle length ({cycle} mm) is taken from them at power-on, when they hold their power-on values again: writing them changes no move</source>
        <translation>{ids}: la longitud del ciclo ({cycle} mm) se toma de ellos al encender, cuando vuelven a tener sus valores de encendido: escribirlos no cambia ningún movimiento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the firmware recomputes {id} after every set: this value will not stay</source>
        <translation>el firmware recalcula {id} tras cada escritura: este valor no se mantendrá</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the firmware recomputes {id} at every move: this value will not stay</source>
        <translation>el firmware recalcula {id} en cada movimiento: este valor no se mantendrá</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the firmware forces 27 to 1 after every set: this value will not stay</source>
        <translation>el firmware impone 27 = 1 tras cada escritura: este valor no se mantendrá</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>this firmware never reads {id:02d}: writing it changes nothing</source>
        <translation>este firmware nunca lee {id:02d}: escribirlo no cambia nada</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a move with ramps (ramp length above 0) leaves {id} at the ramp&apos;s last delay: this value stays only until then</source>
        <translation>un movimiento con rampas (longitud de rampa mayor que 0) deja {id} en el último retardo de la rampa: este valor solo se mantiene hasta entonces</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>this firmware reads {id:02d} only at boot, when it holds {value} again: writing it changes no move</source>
        <translation>este firmware solo lee {id:02d} al arrancar, cuando vuelve a tener {value}: escribirlo no cambia ningún movimiento</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Current step delay, {axis} axis (left by the firmware&apos;s ramps; this revision times an X step as 15 high plus 16 low, a Y step as 16 twice)</source>
        <translation>Retardo entre pasos actual, eje {axis} (lo dejan las rampas del firmware; esta revisión temporiza un paso de X como 15 en alto más 16 en bajo, y un paso de Y como 16 dos veces)</translation>
    </message>
    <message>
        <source>this firmware revision reads {parameter} only at boot (and keeps pulley values divided by 4): moves do not change until the firmware is fixed</source>
        <translation type="vanished">esta revisión del firmware solo lee {parameter} al arrancar (y guarda los valores de polea divididos por 4): los movimientos no cambian hasta que se corrija el firmware</translation>
    </message>
    <message>
        <source>Note</source>
        <translation type="vanished">Nota</translation>
    </message>
    <message>
        <source>this firmware revision moves by the cycle it computed at boot (10 mm lead screw), whatever 01-04 and 27 say</source>
        <translation type="vanished">esta revisión del firmware se mueve según el ciclo que calculó al arrancar (husillo de 10 mm), digan lo que digan 01-04 y 27</translation>
    </message>
    <message>
        <source>{axis}: the cycle ({cycle:g} mm) and the steps per turn ({steps:g}) must both be above 0</source>
        <translation type="vanished">{axis}: el ciclo ({cycle:g} mm) y los pasos por vuelta ({steps:g}) deben ser ambos mayores que 0</translation>
    </message>
    <message>
        <source>{times} (1 s silence included)</source>
        <translation type="vanished">{times} (incluido 1 s de silencio)</translation>
    </message>
    <message>
        <source>Microsteps per turn</source>
        <translation type="vanished">Micropasos por vuelta</translation>
    </message>
    <message>
        <source>Per step</source>
        <translation type="vanished">Por paso</translation>
    </message>
    <message>
        <source>Steps per mm</source>
        <translation type="vanished">Pasos por mm</translation>
    </message>
    <message>
        <source>A 10 mm move</source>
        <translation type="vanished">Un movimiento de 10 mm</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>Lead-screw pitch of the {axis} axis (mm per turn)</source>
        <translation>Paso del husillo del eje {axis} (mm por vuelta)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Belt pulley diameter of the {axis} axis; sent as mm×10 (38.2 mm -&gt; 000382)</source>
        <translation>Diámetro de la polea de correa del eje {axis}; se envía como mm×10 (38.2 mm -&gt; 000382)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Full steps per motor turn, {axis} axis</source>
        <translation>Pasos completos por vuelta del motor, eje {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Microstepping factor of the {axis} driver</source>
        <translation>Factor de micropasos del driver del eje {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Highest speed allowed on the {axis} axis</source>
        <translation>Velocidad máxima permitida en el eje {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Step delay at the steady speed, {axis} axis (computed by the firmware)</source>
        <translation>Retardo entre pasos a velocidad constante, eje {axis} (calculado por el firmware)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Step delay at the lowest speed, {axis} axis</source>
        <translation>Retardo entre pasos a la velocidad mínima, eje {axis}</translation>
    </message>
    <message>
        <source>Current step delay, {axis} axis (computed by the firmware; this revision times every step from it: one step is twice this delay)</source>
        <translation type="vanished">Retardo entre pasos actual, eje {axis} (calculado por el firmware; esta revisión temporiza cada paso a partir de él: un paso dura el doble de este retardo)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mean step delay while accelerating, {axis} axis (computed by the firmware)</source>
        <translation>Retardo medio entre pasos durante la aceleración, eje {axis} (calculado por el firmware)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Steps spent accelerating, {axis} axis (computed by the firmware)</source>
        <translation>Pasos empleados en acelerar, eje {axis} (calculados por el firmware)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Requested steady speed of the {axis} axis</source>
        <translation>Velocidad constante solicitada para el eje {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Requested acceleration of the {axis} axis</source>
        <translation>Aceleración solicitada para el eje {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Duration of the last move, {axis} axis (computed by the firmware)</source>
        <translation>Duración del último movimiento, eje {axis} (calculada por el firmware)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0 belt pulley, 1 lead screw (this firmware forces 1 after every set)</source>
        <translation>0 polea de correa, 1 husillo (este firmware impone 1 tras cada escritura)</translation>
    </message>
    <message>
        <source>protocol {name!r} is not implemented yet</source>
        <translation type="vanished">el protocolo {name!r} aún no está implementado</translation>
    </message>
    <message>
        <location line="-44"/>
        <source>unknown protocol {name!r} (known: {known})</source>
        <translation>protocolo desconocido {name!r} (conocidos: {known})</translation>
    </message>
    <message>
        <location line="+105"/>
        <source>{protocol} has no stop command: the device finishes what it was sent</source>
        <translation>{protocol} no tiene comando de parada: el dispositivo termina lo que se le envió</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timeout {timeout:g} s refused: it must be positive</source>
        <translation>tiempo de espera de {timeout:g} s rechazado: debe ser positivo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>variant {variant!r} asked for a protocol made as {chosen!r}</source>
        <translation>se pidió la variante {variant!r} para un protocolo creado como {chosen!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>baud {baud} refused: a positive number of bits per second</source>
        <translation>{baud} baudios rechazado: debe ser un número positivo de bits por segundo</translation>
    </message>
    <message>
        <location line="+91"/>
        <source>capture with spy&apos;s default hexdump format: spy://PORT?file=FILE, without raw</source>
        <translation>capturar con el formato hexdump predeterminado de spy: spy://PORT?file=FILE, sin raw</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>both directions run together, nothing tells TX from RX</source>
        <translation>ambos sentidos van mezclados y nada distingue TX de RX</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {number}: spy&apos;s raw format is refused ({why}); {hint}</source>
        <translation>{source} línea {number}: no se admite el formato raw de spy ({why}); {hint}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {number}: not a pyserial spy:// hexdump line: {line!r}</source>
        <translation>{source} línea {number}: no es una línea hexdump de spy:// de pyserial: {line!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {number}: bytes at offset {offset:#06x} of a {direction} call whose earlier lines are missing</source>
        <translation>{source} línea {number}: bytes en el desplazamiento {offset:#06x} de una llamada {direction} cuyas líneas anteriores faltan</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no traffic in it, only control-line events</source>
        <translation>{source}: no contiene tráfico, solo eventos de líneas de control</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no traffic in it (nor spy&apos;s raw format); {hint}</source>
        <translation>{source}: no contiene tráfico (ni está en el formato raw de spy); {hint}</translation>
    </message>
    <message>
        <location line="-25"/>
        <source>{error} (after {rounds} rounds; {acknowledged} of {total} instructions were acknowledged before it)</source>
        <translation>{error} (tras {rounds} rondas; antes se confirmaron {acknowledged} de {total} instrucciones)</translation>
    </message>
    <message>
        <location line="-179"/>
        <source>protocol {name!r} cannot be loaded: {error}</source>
        <translation>el protocolo {name!r} no se puede cargar: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>protocol {name!r}: {target} is not a protocol class</source>
        <translation>protocolo {name!r}: {target} no es una clase de protocolo</translation>
    </message>
    <message>
        <location line="+98"/>
        <source>{source}: {why}</source>
        <translation>{source}: {why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: device {device!r}: {why}</source>
        <translation>{where}: dispositivo {device!r}: {why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bench file</source>
        <translation>archivo de banco</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{path}: no device {name!r} (the bench has {names})</source>
        <translation>{path}: no hay dispositivo {name!r} (el banco tiene {names})</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>{name}</source>
        <translation>{name}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: more than {count:,} steps (lines, arcs and travel moves)</source>
        <translation>{where}: más de {count:,} pasos (líneas, arcos y movimientos en vacío)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: a coordinate that is not a finite number</source>
        <translation>{where}: una coordenada que no es un número finito</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>chord tolerance {tolerance:g} mm must be above 0</source>
        <translation>la tolerancia de cuerda {tolerance:g} mm debe ser mayor que 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DXF drawing</source>
        <translation>dibujo DXF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: not a drawing the panel reads: {why}</source>
        <translation>{where}: no es un dibujo que el panel pueda leer: {why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: no lines, arcs or curves on the chosen layers</source>
        <translation>{name}: no hay líneas, arcos ni curvas en las capas elegidas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: skipped what is not a path: {what}</source>
        <translation>{name}: se omitió lo que no es un trazado: {what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: binary DXF cut short (no EOF at its end)</source>
        <translation>{name}: DXF binario truncado (sin EOF al final)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: a DWG drawing, not DXF (save it as DXF)</source>
        <translation>{name}: es un dibujo DWG, no DXF (guárdelo como DXF)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: not a DXF drawing the panel reads: {why}</source>
        <translation>{name}: no es un dibujo DXF que el panel pueda leer: {why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: $INSUNITS {value!r} is not a unit code</source>
        <translation>{name}: $INSUNITS {value!r} no es un código de unidad</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: no units given ($INSUNITS 0), taken as mm</source>
        <translation>{name}: sin unidades indicadas ($INSUNITS 0), se toman como mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: units $INSUNITS {code} the panel cannot convert to mm</source>
        <translation>{name}: unidades $INSUNITS {code} que el panel no puede convertir a mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} entity {number} ({kind} on layer {layer}): not a drawing the panel reads: {why}</source>
        <translation>{name} entidad {number} ({kind} en la capa {layer}): no es un dibujo que el panel pueda leer: {why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: no layer {layer} with lines, arcs or curves; the drawing&apos;s layers: {layers}</source>
        <translation>{name}: no hay ninguna capa {layer} con líneas, arcos o curvas; capas del dibujo: {layers}</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>{name} line {number}</source>
        <translation>{name} línea {number}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: a comment opened with ( is not closed</source>
        <translation>{where}: un comentario abierto con ( no está cerrado</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word} with R: a full circle needs I/J</source>
        <translation>{where}: {word} con R: un círculo completo necesita I/J</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word}: R {radius:g} mm is less than half the way to the end point ({half:g} mm)</source>
        <translation>{where}: {word}: R {radius:g} mm es menor que la mitad de la distancia al punto final ({half:g} mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word}: the feed rate must be above 0</source>
        <translation>{where}: {word}: el avance debe ser mayor que 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word} needs P, the seconds to dwell</source>
        <translation>{where}: {word} necesita P, los segundos de espera</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word}: a dwell cannot be negative</source>
        <translation>{where}: {word}: una espera no puede ser negativa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word} with no motion mode (G0, G1, G2 or G3) set</source>
        <translation>{where}: {word} sin modo de movimiento (G0, G1, G2 o G3) definido</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: no feed rate (F) set before this {word}</source>
        <translation>{where}: no se ha definido avance (F) antes de este {word}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: no moves and no dwells</source>
        <translation>{name}: ni movimientos ni esperas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word}: arcs in the {plane} plane ({code}) are not supported: only G17 (XY)</source>
        <translation>{where}: {word}: los arcos en el plano {plane} ({code}) no se admiten: solo G17 (XY)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word} needs I and J, or R</source>
        <translation>{where}: {word} necesita I y J, o R</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word}: the centre is {start:g} mm from the start point and {end:g} mm from the end point, not on one circle</source>
        <translation>{where}: {word}: el centro está a {start:g} mm del punto inicial y a {end:g} mm del punto final, no en un mismo círculo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word}: an arc of radius 0</source>
        <translation>{where}: {word}: un arco de radio 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word} is not used by anything on the line</source>
        <translation>{where}: {word} no lo usa nada en la línea</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {first} and {second} cannot be on one line</source>
        <translation>{where}: {first} y {second} no pueden estar en una misma línea</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>{name}: more than {count:,} lines, too many for a program</source>
        <translation>{name}: más de {count:,} líneas, demasiadas para un programa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word!r} is not a G-code word (a letter and a number)</source>
        <translation>{where}: {word!r} no es una palabra G-code (una letra y un número)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word} is not understood</source>
        <translation>{where}: {word} no se entiende</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: skipped what the panel does not do: {words} (on {count} of {total} lines)</source>
        <translation>{name}: se omitió lo que el panel no hace: {words} (en {count} de {total} líneas)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>chord tolerance {value:g} mm refused: it must be above 0</source>
        <translation>se rechaza la tolerancia de cuerda {value:g} mm: debe ser mayor que 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: the program moves {axis} to {value:g} mm, an axis the device does not have (it has {axes}); nothing was sent</source>
        <translation>{where}: el programa mueve {axis} a {value:g} mm, un eje que el dispositivo no tiene (tiene {axes}); no se ha enviado nada</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>{where}: the program would leave the travel box at ({x:g}, {y:g}, {z:g}) mm ({box}); nothing was sent</source>
        <translation>{where}: el programa saldría de la caja de recorrido en ({x:g}, {y:g}, {z:g}) mm ({box}); no se ha enviado nada</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: layers are chosen in DXF files only</source>
        <translation>{file}: las capas solo se eligen en archivos DXF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} entity {number} ({text})</source>
        <translation>{name} entidad {number} ({text})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} element {number} ({text})</source>
        <translation>{name} elemento {number} ({text})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} point {number}</source>
        <translation>{name} punto {number}</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>{where}: speed {speed:g} mm/s refused: the device allows {low:g} to {high:g} mm/s; nothing was sent</source>
        <translation>{where}: se rechaza la velocidad {speed:g} mm/s: el dispositivo admite de {low:g} a {high:g} mm/s; no se ha enviado nada</translation>
    </message>
    <message>
        <location line="-513"/>
        <source>{command} refused: the stepper is not configured for {port} (the board forgets it at each reset, and none is kept for this port); run motionctl --port {port} --protocol firmata config --steps-per-rev 200 --pins 8 9 with your motor&apos;s steps per revolution and pins (or Configure in the panel&apos;s Stepper setup): it is kept and sent again at each run</source>
        <translation>{command} rechazado: el motor paso a paso no está configurado para {port} (la placa lo olvida en cada reinicio y no hay ninguna configuración guardada para este puerto); ejecutar motionctl --port {port} --protocol firmata config --steps-per-rev 200 --pins 8 9 con los pasos por revolución y los pines de su motor (o Configurar en la Configuración del motor del panel): se guarda y se vuelve a enviar en cada ejecución</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>{file} names no protocol (no connection note) and no protocol recognises its traffic: give --protocol</source>
        <translation>{file} no indica ningún protocolo (sin nota de conexión) y ningún protocolo reconoce su tráfico: indicar --protocol</translation>
    </message>
    <message>
        <location line="+388"/>
        <source>The speed cannot be set here: this firmware revision times its steps from step_delay_instantaneous (15, 16) alone, not from input_speed_steady (21, 22). &quot;device:&quot; is the speed X steps at (15 high plus 16 low a step); change 15 and 16 in the parameter table to change it.</source>
        <translation>La velocidad no se puede fijar aquí: esta revisión del firmware temporiza sus pasos solo a partir de step_delay_instantaneous (15, 16), no de input_speed_steady (21, 22). &quot;dispositivo:&quot; es la velocidad a la que avanza X (15 en alto más 16 en bajo por paso); cambiar 15 y 16 en la tabla de parámetros para modificarla.</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Y will not move: at these parameters the firmware&apos;s Y loop makes no step (it runs the ramp count, 0; set 22 and 24 so that the ramp length is above 0)</source>
        <translation>Y no se moverá: con estos parámetros el bucle Y del firmware no da ningún paso (ejecuta el recuento de rampa, 0; fijar 22 y 24 de modo que la longitud de rampa sea mayor que 0)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y moves {moved:.3f} mm, not {asked:.3f}: the firmware&apos;s Y loop runs the ramp count ({loops} of {steps} steps)</source>
        <translation>Y se mueve {moved:.3f} mm, no {asked:.3f}: el bucle Y del firmware ejecuta el recuento de rampa ({loops} de {steps} pasos)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} moves {moved:.3f} mm, not {asked:.3f}: whole steps ({steps}), truncated as the firmware counts</source>
        <translation>{axis} se mueve {moved:.3f} mm, no {asked:.3f}: pasos enteros ({steps}), truncados como cuenta el firmware</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>{protocol} reports where it is: it is asked</source>
        <translation>{protocol} informa de dónde está: se le consulta</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>the program&apos;s moves without a speed would go at the device&apos;s speed, {speed:g} mm/s, outside the {low:g} to {high:g} mm/s it allows: set the speed first; nothing was sent</source>
        <translation>los movimientos del programa sin velocidad irían a la velocidad del dispositivo, {speed:g} mm/s, fuera de los {low:g} a {high:g} mm/s que admite: fijar antes la velocidad; no se ha enviado nada</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {error}; nothing was sent</source>
        <translation>{where}: {error}; no se ha enviado nada</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the program was abandoned during a dwell</source>
        <translation>el programa se abandonó durante una espera</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SVG scale {scale:g} mm per unit must be above 0</source>
        <translation>la escala SVG {scale:g} mm por unidad debe ser mayor que 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SVG drawing</source>
        <translation>dibujo SVG</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: not a shape the panel reads: {why}</source>
        <translation>{where}: no es una forma que el panel pueda leer: {why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: no stroked paths or shapes to run</source>
        <translation>{name}: no hay trazados ni formas con trazo que ejecutar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: skipped {what}</source>
        <translation>{name}: se omitió {what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} line {line}: not SVG: {why}</source>
        <translation>{name} línea {line}: no es SVG: {why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: not an SVG drawing the panel reads: {why}</source>
        <translation>{name}: no es un dibujo SVG que el panel pueda leer: {why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: not an SVG drawing (no svg element)</source>
        <translation>{name}: no es un dibujo SVG (sin elemento svg)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: no width and height in mm, cm, in, pt, pc or px; 1 unit taken as {scale:g} mm</source>
        <translation>{name}: sin ancho ni alto en mm, cm, in, pt, pc o px; 1 unidad se toma como {scale:g} mm</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>{pattern!r} is not a regular expression: {error}</source>
        <translation>{pattern!r} no es una expresión regular: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{pattern!r} is not valid text</source>
        <translation>{pattern!r} no es un texto válido</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{pattern!r}… is too large a regular expression: {error}</source>
        <translation>{pattern!r}… es una expresión regular demasiado grande: {error}</translation>
    </message>
    <message>
        <location line="-353"/>
        <source>{url} is not open</source>
        <translation>{url} no está abierto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>writing to {url} failed: {error}</source>
        <translation>falló la escritura en {url}: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>writing to {url}: only {written} of {total} bytes sent</source>
        <translation>escritura en {url}: solo se enviaron {written} de {total} bytes</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reading from {url} failed: {error}</source>
        <translation>falló la lectura de {url}: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name!r} is not a line the host drives (DTR or RTS)</source>
        <translation>{name!r} no es una línea que controle este equipo (DTR o RTS)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{line} cannot be set</source>
        <translation>no se puede fijar {line}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>setting {line} on {url} failed: {error}</source>
        <translation>falló el ajuste de {line} en {url}: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the server did not confirm the control lines ({what} unanswered); they are set without confirmation (ser2net does not answer when the port it serves has no modem lines, e.g. a pseudo-terminal)</source>
        <translation>el servidor no confirmó las líneas de control ({what} sin respuesta); se fijan sin confirmación (ser2net no responde cuando el puerto que sirve no tiene líneas de módem, p. ej. un pseudoterminal)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a break lasts more than 0 and at most {most:g} s</source>
        <translation>un break dura más de 0 s y como máximo {most:g} s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no break can be sent</source>
        <translation>no se puede enviar un break</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sending a break on {url} failed: {error}</source>
        <translation>falló el envío de un break en {url}: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>break {ms:.0f} ms</source>
        <translation>break {ms:.0f} ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reading {line} on {url} failed: {error}</source>
        <translation>falló la lectura de {line} en {url}: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reading the control lines of {url} failed: {error}</source>
        <translation>falló la lectura de las líneas de control de {url}: {error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a TCP socket</source>
        <translation>un socket TCP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{url} has no modem control lines ({why}): {what}</source>
        <translation>{url} no tiene líneas de control de módem ({why}): {what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a pseudo-terminal</source>
        <translation>un pseudoterminal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>its driver has no modem-line control</source>
        <translation>su driver no controla las líneas de módem</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no port given</source>
        <translation>no se ha indicado ningún puerto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{url} is in use by another program</source>
        <translation>{url} está en uso por otro programa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot open {url}: {error}</source>
        <translation>no se puede abrir {url}: {error}</translation>
    </message>
    <message>
        <location line="-67"/>
        <source>travel limits need a range for each of x, y and z</source>
        <translation>los límites de recorrido necesitan un rango para cada uno de x, y y z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>travel limits for {axis} ({low:g} to {high:g} mm) are not a range: the minimum must be at most the maximum</source>
        <translation>los límites de recorrido de {axis} (de {low:g} a {high:g} mm) no forman un rango: el mínimo no puede superar el máximo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the move</source>
        <translation>el movimiento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} {value:g} mm is outside {low:g}..{high:g} mm</source>
        <translation>{axis} {value:g} mm está fuera de {low:g}..{high:g} mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the stage is outside its travel limits: {what} brings it closer ({details})</source>
        <translation>la platina está fuera de sus límites de recorrido: {what} la acerca a ellos ({details})</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what} refused: {details} (travel limits)</source>
        <translation>se rechaza {what}: {details} (límites de recorrido)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what} clamped to the travel limits: {details}; going to ({x:g}, {y:g}, {z:g}) mm</source>
        <translation>se ajusta {what} a los límites de recorrido: {details}; se va a ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>travel limits {text!r}: write three ranges in mm, X0:X1,Y0:Y1,Z0:Z1 (e.g. -100:100,-50:50,0:20), or none</source>
        <translation>límites de recorrido {text!r}: escribir tres rangos en mm, X0:X1,Y0:Y1,Z0:Z1 (p. ej. -100:100,-50:50,0:20), o none</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>travel limits for {axis}: {part!r} is not MIN:MAX in mm (e.g. -100:100)</source>
        <translation>límites de recorrido de {axis}: {part!r} no es MIN:MAX en mm (p. ej. -100:100)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} {value!r} is not a finite number</source>
        <translation>{name} {value!r} no es un número finito</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} {value:g} mm refused: the device works to {resolution:g} mm (the nearest it can do is {nearest} mm)</source>
        <translation>{name} {value:g} mm rechazado: la resolución del dispositivo es {resolution:g} mm (el valor posible más cercano es {nearest} mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{earlier}; {later}</source>
        <translation>{earlier}; {later}</translation>
    </message>
    <message>
        <location line="+300"/>
        <source>expected a sim:// URL, got {url!r}</source>
        <translation>se esperaba una URL sim://, se recibió {url!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown sim:// option {key!r}</source>
        <translation>opción sim:// desconocida {key!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>port must be configured before it can be used</source>
        <translation>el puerto debe configurarse antes de poder usarlo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>port already open</source>
        <translation>el puerto ya está abierto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot open {port}: {error}</source>
        <translation>no se puede abrir {port}: {error}</translation>
    </message>
    <message>
        <location line="-273"/>
        <source>{where} accepted this connection and closed it at once{said}: another client probably holds the port (ser2net serves one at a time with max-connections: 1); close it there first</source>
        <translation>{where} aceptó esta conexión y la cerró de inmediato{said}: probablemente otro cliente tiene el puerto (ser2net atiende a uno cada vez con max-connections: 1); cerrar primero ese cliente</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the server has not reported the modem lines</source>
        <translation>el servidor no ha informado de las líneas de módem</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nothing answers at {where} ({error}): is ser2net (or another RFC 2217 server) running there and serving that port?</source>
        <translation>nada responde en {where} ({error}): ¿se está ejecutando allí ser2net (u otro servidor RFC 2217) y sirve ese puerto?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where} answers, but not as an RFC 2217 server: serve the port with ser2net&apos;s `accepter: telnet(rfc2217),tcp,PORT`, or open a raw TCP server as socket://{where}</source>
        <translation>{where} responde, pero no como servidor RFC 2217: servir el puerto con `accepter: telnet(rfc2217),tcp,PORT` de ser2net, o abrir un servidor TCP en bruto como socket://{where}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timeout while waiting for option &apos;purge&apos;</source>
        <translation>tiempo de espera agotado al esperar la opción &apos;purge&apos;</translation>
    </message>
    <message>
        <location line="-34"/>
        <source>no axis {axis!r}: x, y or z</source>
        <translation>no existe el eje {axis!r}: x, y o z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>work zero at home (work = machine)</source>
        <translation>cero de pieza en el origen (trabajo = máquina)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>work zero at ({x:g}, {y:g}, {z:g}) mm machine</source>
        <translation>cero de pieza en ({x:g}, {y:g}, {z:g}) mm de máquina</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>work zero {text!r} is not three numbers x,y,z</source>
        <translation>cero de pieza {text!r}: no son tres números x,y,z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>work zero {text!r} is not three finite numbers x,y,z</source>
        <translation>cero de pieza {text!r}: no son tres números finitos x,y,z</translation>
    </message>
</context>
</TS>
