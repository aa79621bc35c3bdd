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
        <location filename="../../widgets/arc_entry.py" line="+126"/>
        <source>X of the arc&apos;s centre, in mm from home</source>
        <translation>X del centro del arco, en mm desde el origen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Y of the arc&apos;s centre, in mm from home</source>
        <translation>Y del centro del arco, en mm desde el origen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Radius of the arc, in mm (more than 0)</source>
        <translation>Radio del arco, en mm (mayor que 0)</translation>
    </message>
    <message>
        <location line="+6"/>
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
        <location line="+7"/>
        <source>Z at the end of the arc, in mm; Z moves evenly from the current Z along the arc
(a helix when it differs)</source>
        <translation>Z al final del arco, en mm; Z avanza de forma uniforme desde la Z actual a lo largo del arco
(una hélice si es distinta)</translation>
    </message>
    <message>
        <location line="+15"/>
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
        <location line="+11"/>
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
        <location line="+130"/>
        <source>Move along the arc, from its start point to its end point</source>
        <translation>Moverse a lo largo del arco, desde su punto inicial hasta su punto final</translation>
    </message>
    <message>
        <location line="-122"/>
        <source>Why the arc cannot run</source>
        <translation>Por qué no se puede ejecutar el arco</translation>
    </message>
    <message>
        <location line="+128"/>
        <source>The radius must be more than 0 mm.</source>
        <translation>El radio debe ser mayor que 0 mm.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 %2 to %3 mm (travel %4 to %5 mm)</source>
        <translation>%1 de %2 a %3 mm (recorrido de %4 a %5 mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 %2 mm (travel %3 to %4 mm)</source>
        <translation>%1 %2 mm (recorrido de %3 a %4 mm)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The arc leaves the travel limits: %1.</source>
        <translation>El arco sale de los límites de recorrido: %1.</translation>
    </message>
</context>
<context>
    <name>BridgeSession</name>
    <message>
        <location filename="../../app/bridge_session.py" line="+82"/>
        <source>the bridge failed: %1</source>
        <translation>el puente falló: %1</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>the bridge stopped</source>
        <translation>el puente se detuvo</translation>
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
        <location line="+42"/>
        <source>/dev/ttyUSB0, COM3 or a URL</source>
        <translation>/dev/ttyUSB0, COM3 o una URL</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Serial port, or any pyserial URL (e.g. sim://coxiris, socket://host:port, loop://)</source>
        <translation>Puerto serie, o cualquier URL de pyserial (p. ej. sim://coxiris, socket://host:port, loop://)</translation>
    </message>
    <message>
        <location line="+13"/>
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
        <location line="+224"/>
        <source>Connect</source>
        <translation>Conectar</translation>
    </message>
    <message>
        <location line="-224"/>
        <location line="+223"/>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <location line="-223"/>
        <location line="+223"/>
        <source>Disconnect</source>
        <translation>Desconectar</translation>
    </message>
    <message>
        <location line="-213"/>
        <source>Lines:</source>
        <translation>Líneas:</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Port:</source>
        <translation>Puerto:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Protocol:</source>
        <translation>Protocolo:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Baud:</source>
        <translation>Baudios:</translation>
    </message>
    <message>
        <location line="+68"/>
        <source>No description for this port</source>
        <translation>Sin descripción para este puerto</translation>
    </message>
    <message>
        <location line="+111"/>
        <source>● %1: %2</source>
        <translation>● %1: %2</translation>
    </message>
    <message>
        <location line="+21"/>
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
        <location filename="../../widgets/control_lines_bar.py" line="+42"/>
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
        <location filename="../../widgets/coordinate_entry.py" line="+33"/>
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
        <location line="+41"/>
        <source>%1:</source>
        <comment>an axis field&apos;s label</comment>
        <translation>%1:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Absolute</source>
        <translation>Absoluto</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Go to the typed coordinates (mm from home)</source>
        <translation>Ir a las coordenadas introducidas (mm desde el origen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Relative</source>
        <translation>Relativo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Move by the typed distances (mm) from where the stage is</source>
        <translation>Mover las distancias introducidas (mm) desde la posición actual de la platina</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Machine</source>
        <translation>Máquina</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Work</source>
        <translation>Trabajo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Which frame the typed coordinates are in: Machine (mm from the device&apos;s home) or Work (mm from the work zero); the device is always sent machine coordinates</source>
        <translation>Sistema de las coordenadas introducidas: Máquina (mm desde el origen del dispositivo) o Trabajo (mm desde el cero de pieza); al dispositivo siempre se le envían coordenadas de máquina</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Go</source>
        <translation>Ir</translation>
    </message>
    <message>
        <location line="+0"/>
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
        <location line="+127"/>
        <source>Stop</source>
        <translation>Detener</translation>
    </message>
    <message>
        <location line="-127"/>
        <source>Stop the stage now</source>
        <translation>Detener la platina ahora</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the stage now (Esc)</source>
        <translation>Detener la platina ahora (Esc)</translation>
    </message>
    <message>
        <location line="+126"/>
        <source>Drop queued</source>
        <translation>Descartar cola</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1 distance to move, %2 to %3 mm (%4)</source>
        <translation>Distancia a mover en %1, de %2 a %3 mm (%4)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 target coordinate, %2 to %3 mm (%4)</source>
        <translation>Coordenada de destino %1, de %2 a %3 mm (%4)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 target coordinate in the work frame, %2 to %3 mm (%4)</source>
        <translation>Coordenada de destino %1 en el sistema de trabajo, de %2 a %3 mm (%4)</translation>
    </message>
    <message>
        <location line="+2"/>
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
</context>
<context>
    <name>DerivedValues</name>
    <message>
        <location filename="../../widgets/parameter_table.py" line="+445"/>
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
        <location filename="../../app/device_docks.py" line="+135"/>
        <source>%1 to %2 mm on every axis (16-bit ticks)</source>
        <translation>%1 a %2 mm en cada eje (cuentas de 16 bits)</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>program %1: %2 points, nothing sent yet</source>
        <translation>programa %1: %2 puntos, aún no se ha enviado nada</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>program saved to %1 (%2 points)</source>
        <translation>programa guardado en %1 (%2 puntos)</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>the program stopped: %1</source>
        <translation>el programa se detuvo: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>program %1 done: %2/%3 executed, %4 frames, %5 retransmission(s), %6 s</source>
        <translation>programa %1 terminado: %2/%3 ejecutadas, %4 tramas, %5 retransmisión(es), %6 s</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>program %1 stopped, the device&apos;s queue flushed: %2/%3 executed, %4 frames, %5 retransmission(s), %6 s</source>
        <translation>programa %1 detenido, cola del dispositivo vaciada: %2/%3 ejecutadas, %4 tramas, %5 retransmisión(es), %6 s</translation>
    </message>
</context>
<context>
    <name>DockLayout</name>
    <message>
        <location filename="../../app/dock_layout.py" line="+16"/>
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
</context>
<context>
    <name>DwellEntry</name>
    <message>
        <location filename="../../widgets/dwell_entry.py" line="+26"/>
        <source>Dwell:</source>
        <translation>Espera:</translation>
    </message>
    <message>
        <location line="+11"/>
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
</context>
<context>
    <name>FirmataPanel</name>
    <message>
        <location filename="../../widgets/firmata_panel.py" line="+30"/>
        <source>version unknown</source>
        <translation>versión desconocida</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Full steps per revolution of the motor, 1 to %1 (e.g. 200)</source>
        <translation>Pasos completos por revolución del motor, de 1 a %1 (p. ej. 200)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 pins</source>
        <translation>%1 pines</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>2 pins: a driver with step and direction inputs; 4 pins: the motor&apos;s four wires</source>
        <translation>2 pines: un driver con entradas de paso y dirección; 4 pines: los cuatro hilos del motor</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>pin </source>
        <translation>pin </translation>
    </message>
    <message>
        <location line="+19"/>
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
        <location filename="../../app/jobs.py" line="+25"/>
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
        <location filename="../../widgets/jog_panel.py" line="+30"/>
        <source>Keys: ←/→ X, ↑/↓ Y, PgUp/PgDn Z, Shift ×10</source>
        <translation>Teclas: ←/→ X, ↑/↓ Y, PgUp/PgDn Z, Shift ×10</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>Move the stage by one step; hold a button or key to keep stepping.
%1 (see the hint below for where the keys work).</source>
        <translation>Mover la platina un paso; mantener pulsado un botón o una tecla para seguir avanzando.
%1 (la indicación de abajo dice dónde funcionan las teclas).</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Step:</source>
        <translation>Paso:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Distance of one jog</source>
        <translation>Distancia de un desplazamiento</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Jog by %1 per press</source>
        <translation>Desplazar %1 por pulsación</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Any step size (0.001 to 1000 mm)</source>
        <translation>Cualquier tamaño de paso (de 0.001 a 1000 mm)</translation>
    </message>
    <message>
        <location line="+27"/>
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
        <location line="+66"/>
        <source>Jog %1 by %2 mm (Shift: %3 mm)</source>
        <translation>Desplazar %1 %2 mm (Shift: %3 mm)</translation>
    </message>
</context>
<context>
    <name>KeyboardJog</name>
    <message>
        <location filename="../../app/keyboard_jog.py" line="+38"/>
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
        <location line="+57"/>
        <source>not connected</source>
        <translation>no conectado</translation>
    </message>
    <message>
        <location line="+2"/>
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
        <location filename="../../app/log_viewer.py" line="+42"/>
        <source>(undecoded)</source>
        <translation>(sin decodificar)</translation>
    </message>
    <message>
        <location line="+21"/>
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
        <source>Protocol:</source>
        <translation>Protocolo:</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>reading %1…</source>
        <translation>leyendo %1…</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>%1 — traffic log</source>
        <translation>%1 — registro de tráfico</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2): %3 lines, decoded as %4</source>
        <translation>%1 (%2): %3 líneas, decodificadas como %4</translation>
    </message>
</context>
<context>
    <name>MacroDock</name>
    <message>
        <location filename="../../app/macro_dock.py" line="+28"/>
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
        <location line="+42"/>
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
        <location line="+4"/>
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
        <location line="+33"/>
        <source>Run %1:
%2</source>
        <translation>Ejecutar %1:
%2</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <location filename="../../app/main_window.py" line="+102"/>
        <source>%1 has no stop command: this drops the commands not yet sent; a move already under way on the device finishes (Esc)</source>
        <translation>%1 no tiene comando de parada: esto descarta los comandos aún no enviados; un movimiento ya en curso en el dispositivo termina (Esc)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Stop the stage now: halts the move under way and drops what is queued (Esc)</source>
        <translation>Detener la platina ahora: interrumpe el movimiento en curso y descarta lo que está en cola (Esc)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>simulated %1 device</source>
        <translation>dispositivo %1 simulado</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Motion Panel</source>
        <translation>Motion Panel</translation>
    </message>
    <message>
        <location line="+106"/>
        <source>no session log: %1</source>
        <translation>sin registro de sesión: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>session log: %1</source>
        <translation>registro de sesión: %1</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Connection</source>
        <translation>Conexión</translation>
    </message>
    <message>
        <location line="+29"/>
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
        <location line="+12"/>
        <source>Traffic timeline</source>
        <translation>Línea de tiempo del tráfico</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Export traffic log…</source>
        <translation>&amp;Exportar registro de tráfico…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Save every byte sent and received, with timestamps, to a text file</source>
        <translation>Guardar cada byte enviado y recibido, con marcas de tiempo, en un archivo de texto</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Open log…</source>
        <translation>&amp;Abrir registro…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Browse a traffic log (ours or a pyserial spy:// capture) decoded</source>
        <translation>Ver decodificado un registro de tráfico (de este panel o una captura spy:// de pyserial)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open the session &amp;log folder</source>
        <translation>Abrir la carpeta del &amp;registro de sesión</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every byte of every session is kept there, one file a session</source>
        <translation>Allí se guarda cada byte de cada sesión, un archivo por sesión</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Motion</source>
        <translation>&amp;Movimiento</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+351"/>
        <source>&amp;Stop</source>
        <translation>&amp;Detener</translation>
    </message>
    <message>
        <location line="-346"/>
        <source>&amp;Travel limits…</source>
        <translation>&amp;Límites de recorrido…</translation>
    </message>
    <message>
        <location line="+2"/>
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
        <location line="+134"/>
        <source>connecting to %1 (%2, %3 baud)</source>
        <translation>conectando con %1 (%2, %3 baudios)</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>bridge refused: %1</source>
        <translation>puente rechazado: %1</translation>
    </message>
    <message>
        <location line="+5"/>
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
        <location line="+16"/>
        <source>connection error: %1</source>
        <translation>error de conexión: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>disconnected</source>
        <translation>desconectado</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>connected to %1 on %2</source>
        <translation>conectado a %1 en %2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the position is unknown: this device cannot report it; home it or set home</source>
        <translation>la posición es desconocida: este dispositivo no puede informar de ella; buscar el origen o fijar el origen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>connected again to %1: the position was read again</source>
        <translation>reconectado a %1: se ha vuelto a leer la posición</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>the device</source>
        <translation>el dispositivo</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Go to the home position (0, 0, 0)</source>
        <translation>Ir a la posición de origen (0, 0, 0)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Make the current position the origin (asks first)</source>
        <translation>Convertir la posición actual en el origen (pide confirmación)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Restart the panel&apos;s count of the position here (asks first); %1 has no set-home command, so nothing is sent</source>
        <translation>Reiniciar aquí el conteo de posición del panel (pide confirmación); %1 no tiene comando para fijar el origen, así que no se envía nada</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&amp;Drop queued commands</source>
        <translation>&amp;Descartar comandos en cola</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>port %1 appeared</source>
        <translation>apareció el puerto %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>reconnecting to %1</source>
        <translation>reconectando con %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>port %1 disappeared</source>
        <translation>desapareció el puerto %1</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>%1 on %2</source>
        <translation>%1 en %2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>travel limits: %1</source>
        <translation>límites de recorrido: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>not connected: %1 not sent</source>
        <translation>no conectado: %1 sin enviar</translation>
    </message>
    <message>
        <location line="+79"/>
        <source>stopping the macro under way</source>
        <translation>deteniendo la macro en curso</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>stopping the move under way</source>
        <translation>deteniendo el movimiento en curso</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>nothing queued; the move under way finishes</source>
        <translation>nada en cola; el movimiento en curso termina</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>stopped: %1 command(s) not sent: %2</source>
        <translation>detenido: %1 comando(s) sin enviar: %2</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>new home: the trail is shifted by (%1, %2, %3) mm</source>
        <translation>nuevo origen: la trayectoria se desplaza (%1, %2, %3) mm</translation>
    </message>
    <message>
        <location line="+75"/>
        <source>the device reported an error: %1</source>
        <translation>el dispositivo informó de un error: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>device: %1</source>
        <translation>dispositivo: %1</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 failed: %2</source>
        <translation>%1 falló: %2</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>speed %1 mm/s reads back as %2 mm/s (the device rounds)</source>
        <translation>la velocidad %1 mm/s se relee como %2 mm/s (el dispositivo redondea)</translation>
    </message>
</context>
<context>
    <name>ParameterDock</name>
    <message>
        <location filename="../../app/parameter_dock.py" line="+30"/>
        <source>the device now holds %1: the firmware forces it after every set</source>
        <translation>el dispositivo tiene ahora %1: el firmware lo impone tras cada escritura</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Parameters</source>
        <translation>Parámetros</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>Parameters (%1)</source>
        <translation>Parámetros (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 on %2</source>
        <translation>%1 en %2</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>parameter writing cancelled: %1 not sent</source>
        <translation>escritura de parámetros cancelada: %1 sin enviar</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>not sent</source>
        <translation>sin enviar</translation>
    </message>
    <message>
        <location line="+28"/>
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
        <location line="+15"/>
        <source>saved %1 values to %2</source>
        <translation>%1 valores guardados en %2</translation>
    </message>
</context>
<context>
    <name>ParameterEditor</name>
    <message>
        <location filename="../../widgets/parameter_editor.py" line="+44"/>
        <source>Parameter profiles (*.toml);;All files (*)</source>
        <translation>Perfiles de parámetros (*.toml);;Todos los archivos (*)</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>The device cannot be read back: this compares with what this panel last wrote</source>
        <translation>El dispositivo no se puede releer: se compara con lo último que escribió este panel</translation>
    </message>
    <message>
        <location line="+11"/>
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
        <location line="+2"/>
        <source>Write the values marked • (not yet written)</source>
        <translation>Escribir los valores marcados con • (aún sin escribir)</translation>
    </message>
    <message>
        <location line="+3"/>
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
        <location line="+54"/>
        <source>Not loaded: %1</source>
        <translation>No cargado: %1</translation>
    </message>
    <message>
        <location line="+120"/>
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
        <location line="+4"/>
        <source>nothing differs</source>
        <translation>no hay diferencias</translation>
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
        <location line="+2"/>
        <source>computed by the firmware, which may replace them: %1</source>
        <translation>calculados por el firmware, que puede reemplazarlos: %1</translation>
    </message>
    <message>
        <location line="+10"/>
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
        <location filename="../../widgets/parameter_table.py" line="-411"/>
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
        <location line="+12"/>
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
        <location line="+97"/>
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
        <location line="+5"/>
        <source>%1: never written to this device from this panel</source>
        <translation>%1: nunca escrito en este dispositivo desde este panel</translation>
    </message>
    <message>
        <location line="+2"/>
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
        <location line="+57"/>
        <source>%1: no such parameter</source>
        <translation>%1: no existe ese parámetro</translation>
    </message>
</context>
<context>
    <name>ParameterTableView</name>
    <message>
        <location line="+157"/>
        <source>Double-click a value, or select a row and press Enter or type, to edit</source>
        <translation>Para editar, hacer doble clic en un valor, o seleccionar una fila y pulsar Enter o escribir</translation>
    </message>
</context>
<context>
    <name>ParameterValues</name>
    <message>
        <location filename="../../widgets/parameter_values.py" line="+38"/>
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
        <location line="+10"/>
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
        <location line="+14"/>
        <source>%1: %2 refused (%3): %4</source>
        <translation>%1: %2 rechazado (%3): %4</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>empty</source>
        <translation>vacío</translation>
    </message>
    <message>
        <location line="+3"/>
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
        <location filename="../../widgets/piframe_panel.py" line="+15"/>
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
        <location line="+25"/>
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
        <location filename="../../app/ports.py" line="+22"/>
        <source>serial port</source>
        <translation>puerto serie</translation>
    </message>
</context>
<context>
    <name>PositionReadout</name>
    <message>
        <location filename="../../widgets/position_readout.py" line="+27"/>
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
        <source>last known position: not connected</source>
        <translation>última posición conocida: no conectado</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Stage position in mm: from the device&apos;s home, and from the work zero</source>
        <translation>Posición de la platina en mm: desde el origen del dispositivo y desde el cero de pieza</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Machine</source>
        <translation>Máquina</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Millimetres from the device&apos;s home (its origin)</source>
        <translation>Milímetros desde el origen del dispositivo (su posición de referencia)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Work</source>
        <translation>Trabajo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Millimetres from the work zero the panel keeps (the device is not told)</source>
        <translation>Milímetros desde el cero de pieza que guarda el panel (no se comunica al dispositivo)</translation>
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
        <location line="+188"/>
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
        <source>%1 position in mm from the device&apos;s home</source>
        <translation>Posición %1 en mm desde el origen del dispositivo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 position in mm from the work zero</source>
        <translation>Posición %1 en mm desde el cero de pieza</translation>
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
        <location filename="../../widgets/position_view_2d.py" line="+85"/>
        <source>Stage seen from above: trail, current position (dot; hollow when estimated), target (+), travel limits (dashed)</source>
        <translation>Platina vista desde arriba: trayectoria, posición actual (punto; hueco si es estimada), destino (+), límites de recorrido (discontinuos)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>XY (from above)</source>
        <translation>XY (desde arriba)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X (mm)</source>
        <translation>X (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y (mm)</source>
        <translation>Y (mm)</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>X, Y and Z against time; dashed lines: target</source>
        <translation>X, Y y Z en función del tiempo; líneas discontinuas: destino</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Position against time</source>
        <translation>Posición en función del tiempo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>time (s, 0 = latest sample)</source>
        <translation>tiempo (s, 0 = última muestra)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position (mm)</source>
        <translation>posición (mm)</translation>
    </message>
    <message>
        <location line="+18"/>
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
        <location filename="../../widgets/_gl_scene.py" line="+43"/>
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
        <location filename="../../widgets/position_view_3d.py" line="+75"/>
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
        <location line="+164"/>
        <source>Drag to rotate, wheel to zoom, middle-drag to pan</source>
        <translation>Arrastrar para girar, rueda para hacer zoom, arrastrar con el botón central para mover la vista</translation>
    </message>
    <message>
        <location line="+364"/>
        <source>grid %1 mm</source>
        <translation>cuadrícula %1 mm</translation>
    </message>
</context>
<context>
    <name>Preferences</name>
    <message>
        <location filename="../../app/preferences.py" line="+67"/>
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
        <location line="+52"/>
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
    <name>ProgramPanel</name>
    <message>
        <location filename="../../widgets/program_panel.py" line="+19"/>
        <source>Programs (*.csv *.json);;All files (*)</source>
        <translation>Programas (*.csv *.json);;Todos los archivos (*)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no program loaded</source>
        <translation>ningún programa cargado</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Load…</source>
        <translation>Cargar…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Load a program: CSV with x,y,z,speed (mm, mm/s) or JSON</source>
        <translation>Cargar un programa: CSV con x,y,z,speed (mm, mm/s) o JSON</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save…</source>
        <translation>Guardar…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save the loaded program as JSON (x, y, z, speed per point)</source>
        <translation>Guardar el programa cargado como JSON (x, y, z, speed por punto)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Run</source>
        <translation>Ejecutar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stream the program to the device, 7 moves a frame</source>
        <translation>Enviar el programa al dispositivo en flujo continuo, 7 movimientos por trama</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+102"/>
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <location line="-100"/>
        <source>Send nothing more until Resume (queued moves go on)</source>
        <translation>No enviar nada más hasta Reanudar (los movimientos en cola continúan)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Stop</source>
        <translation>Detener</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Send nothing more and flush the device&apos;s queue (STOP)</source>
        <translation>No enviar nada más y vaciar la cola del dispositivo (STOP)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Instructions executed by the device</source>
        <translation>Instrucciones ejecutadas por el dispositivo</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+69"/>
        <source>%v / %m executed</source>
        <translation>%v / %m ejecutadas</translation>
    </message>
    <message>
        <location line="-50"/>
        <source>Program:</source>
        <translation>Programa:</translation>
    </message>
    <message>
        <location line="+15"/>
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
        <location line="+24"/>
        <source>%1 (%2 points)</source>
        <translation>%1 (%2 puntos)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no program</source>
        <translation>sin programa</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Resume</source>
        <translation>Reanudar</translation>
    </message>
    <message>
        <location line="+14"/>
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
        <location filename="../../app/traffic_console.py" line="+72"/>
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
        <location line="+13"/>
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
        <location line="+89"/>
        <source>Bytes as text (\r \n \xNN escapes), hex (47 45 54), or mixed (text, &lt;0A&gt; for the rest)</source>
        <translation>Bytes como texto (escapes \r \n \xNN), hex (47 45 54) o mixto (texto, &lt;0A&gt; para el resto)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Times: seconds since the session start, wall-clock time, or the gap since the line above</source>
        <translation>Tiempos: segundos desde el inicio de la sesión, hora del reloj o intervalo desde la línea anterior</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Time</source>
        <translation>Tiempo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Show the time column</source>
        <translation>Mostrar la columna de tiempo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>TX</source>
        <translation>TX</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Show what was sent to the device</source>
        <translation>Mostrar lo enviado al dispositivo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>RX</source>
        <translation>RX</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Show what the device sent</source>
        <translation>Mostrar lo que envió el dispositivo</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Kinds</source>
        <translation>Tipos</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Which kinds of lines to show</source>
        <translation>Qué tipos de líneas mostrar</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Poll</source>
        <translation>Consulta</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Show the idle position queries and their replies (hidden by default; counted below)</source>
        <translation>Mostrar las consultas de posición en reposo y sus respuestas (ocultas por defecto; se cuentan abajo)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>filter (regex)</source>
        <translation>filtro (regex)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Show only lines matching this regular expression (case-insensitive) in their direction, kind, hex, text or meaning, e.g. error|FA00</source>
        <translation>Mostrar solo las líneas que coinciden con esta expresión regular (sin distinguir mayúsculas) en su dirección, tipo, hex, texto o significado, p. ej. error|FA00</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>paused</source>
        <translation>en pausa</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>New lines do not scroll the view: scroll to the bottom to follow</source>
        <translation>Las líneas nuevas no desplazan la vista: bajar hasta el final para seguirlas</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>search (regex)</source>
        <translation>buscar (regex)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Highlight matching lines; Enter or F3: next, Shift+F3: previous</source>
        <translation>Resaltar las líneas coincidentes; Enter o F3: siguiente, Shift+F3: anterior</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Previous match (Shift+F3)</source>
        <translation>Coincidencia anterior (Shift+F3)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Next match (F3)</source>
        <translation>Coincidencia siguiente (F3)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Lines in the session, shown, hidden polls, errors, matches</source>
        <translation>Líneas de la sesión, mostradas, consultas ocultas, errores, coincidencias</translation>
    </message>
    <message>
        <location line="+3"/>
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
        <location line="+24"/>
        <source>TX (blue): sent to the device; RX (green): received; grey: notes and the device&apos;s own text; red: errors. Double-click a line to go to its request, reply or first copy.</source>
        <translation>TX (azul): enviado al dispositivo; RX (verde): recibido; gris: notas y texto propio del dispositivo; rojo: errores. Doble clic en una línea para ir a su petición, su respuesta o su primera copia.</translation>
    </message>
    <message>
        <location line="+144"/>
        <source>%1 lines reached the console&apos;s limit and were cleared; the session log keeps them</source>
        <translation>%1 líneas alcanzaron el límite de la consola y se borraron; el registro de sesión las conserva</translation>
    </message>
    <message>
        <location line="+260"/>
        <source>%1 lines</source>
        <translation>%1 líneas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 shown</source>
        <translation>%1 mostradas</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 poll hidden</source>
        <translation>%1 de consulta ocultas</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 errors</source>
        <translation>%1 errores</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 matches</source>
        <translation>%1 coincidencias</translation>
    </message>
    <message>
        <location line="+85"/>
        <source>export failed: %1</source>
        <translation>exportación fallida: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>exported %1 lines to %2</source>
        <translation>%1 líneas exportadas a %2</translation>
    </message>
    <message>
        <location filename="../../app/traffic_table.py" line="+44"/>
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
        <location line="+42"/>
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
        <location filename="../../widgets/settings_dialog.py" line="+87"/>
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
        <location line="+10"/>
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
        <location line="+101"/>
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
        <location line="+4"/>
        <source>The most lines the console keeps: 0 keeps every line (a spool file on disk and about 33 bytes a line in memory), else %1 to %2 lines. The session log keeps every byte either way.</source>
        <translation>Máximo de líneas que conserva la consola: 0 conserva todas (un archivo de volcado en disco y unos 33 bytes por línea en memoria); si no, de %1 a %2 líneas. El registro de sesión conserva todos los bytes en cualquier caso.</translation>
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
        <location line="+26"/>
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
        <location filename="../../widgets/speed_control.py" line="+35"/>
        <source>Speed:</source>
        <translation>Velocidad:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed of the next moves</source>
        <translation>Velocidad de los próximos movimientos</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Apply</source>
        <translation>Aplicar</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+34"/>
        <source>Send the speed in the field to the device</source>
        <translation>Enviar al dispositivo la velocidad del campo</translation>
    </message>
    <message>
        <location line="-29"/>
        <source>The speed the device reports (it may round)</source>
        <translation>La velocidad que indica el dispositivo (puede redondearla)</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>Speed, %1 to %2 mm/s; press Enter or Apply to send</source>
        <translation>Velocidad, de %1 a %2 mm/s; pulsar Enter o Aplicar para enviar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Drag and release to send (%1 to %2 mm/s)</source>
        <translation>Arrastrar y soltar para enviar (%1 a %2 mm/s)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>device: %1 mm/s</source>
        <translation>dispositivo: %1 mm/s</translation>
    </message>
</context>
<context>
    <name>StatusLine</name>
    <message>
        <location filename="../../widgets/status_line.py" line="+18"/>
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
        <location line="+39"/>
        <source>Connecting…</source>
        <translation>Conectando…</translation>
    </message>
    <message>
        <location line="-37"/>
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
        <location filename="../../app/theme.py" line="+354"/>
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
    <name>TrafficModel</name>
    <message>
        <location filename="../../app/traffic_table.py" line="-19"/>
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
        <location line="+249"/>
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
        <location filename="../../widgets/traffic_timeline.py" line="+38"/>
        <source>TX</source>
        <translation>TX</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RX</source>
        <translation>RX</translation>
    </message>
    <message>
        <location line="+206"/>
        <source>Follow</source>
        <translation>Seguir</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Keep the latest %1 s in view; zooming or panning stops it</source>
        <translation>Mantener a la vista los últimos %1 s; hacer zoom o mover la vista lo desactiva</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Bytes per second each way, in one-second bins: TX (blue) sent to the device, RX (green) received. Click a bin to show its first line in the console.</source>
        <translation>Bytes por segundo en cada sentido, en intervalos de un segundo: TX (azul) enviado al dispositivo, RX (verde) recibido. Hacer clic en un intervalo para mostrar su primera línea en la consola.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>rate</source>
        <translation>tasa</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Bytes per second</source>
        <translation>Bytes por segundo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Command latency</source>
        <translation>Latencia de comandos</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Time from a request to its reply, in ms: one point per answered request (drawn as dots when few are in view). Click a point to show its line in the console.</source>
        <translation>Tiempo entre una petición y su respuesta, en ms: un punto por petición respondida (dibujados como marcadores cuando hay pocos a la vista). Hacer clic en un punto para mostrar su línea en la consola.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>latency</source>
        <translation>latencia</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>time since the session started</source>
        <translation>tiempo desde el inicio de la sesión</translation>
    </message>
</context>
<context>
    <name>TravelLimitsDialog</name>
    <message>
        <location filename="../../widgets/travel_limits_dialog.py" line="+32"/>
        <source>Travel limits</source>
        <translation>Límites de recorrido</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Where the stage may go on %1. A jog, go-to or command-line move that would leave the box is refused before anything is sent, or clamped to its edge.</source>
        <translation>Zona por la que puede moverse la platina en %1. Un desplazamiento, un Ir a o un movimiento desde la línea de comandos que saldría de la caja se rechaza antes de enviar nada, o se ajusta a su borde.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Limit moves to this box</source>
        <translation>Limitar los movimientos a esta caja</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>min</source>
        <translation>mín</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max</source>
        <translation>máx</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1:</source>
        <comment>an axis field&apos;s label</comment>
        <translation>%1:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Refuse a move that would leave the box</source>
        <translation>Rechazar un movimiento que saldría de la caja</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Clamp it: go as far as the edge, and say so</source>
        <translation>Ajustarlo: ir hasta el borde e indicarlo</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>%1: the minimum must be below the maximum</source>
        <translation>%1: el mínimo debe ser menor que el máximo</translation>
    </message>
</context>
<context>
    <name>ValueDelegate</name>
    <message>
        <location filename="../../widgets/parameter_table.py" line="-95"/>
        <source>%1: edit cancelled, value unchanged</source>
        <translation>%1: edición cancelada, valor sin cambios</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 is an output. %2</source>
        <translation>%1 es una salida. %2</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1 = %2, not yet written to the device</source>
        <translation>%1 = %2, aún no escrito en el dispositivo</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1: %2 (Enter keeps it, Escape cancels)</source>
        <translation>%1: %2 (Enter lo conserva, Esc cancela)</translation>
    </message>
</context>
<context>
    <name>WindowTools</name>
    <message>
        <location filename="../../app/window_tools.py" line="+58"/>
        <source>Macros</source>
        <translation>Macros</translation>
    </message>
    <message>
        <location line="+28"/>
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
        <location line="+53"/>
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
        <location line="+42"/>
        <source>the session log from the next start</source>
        <translation>el registro de sesión se aplica en el próximo inicio</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the language from the next start</source>
        <translation>el idioma se aplica en el próximo inicio</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>settings saved</source>
        <translation>ajustes guardados</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>settings saved; %1</source>
        <translation>ajustes guardados; %1</translation>
    </message>
</context>
<context>
    <name>WorkFrame</name>
    <message>
        <location filename="../../app/work_frame.py" line="+58"/>
        <source>work coordinates: %1</source>
        <translation>coordenadas de trabajo: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>work zero not set: the position is unknown</source>
        <translation>cero de pieza no fijado: la posición es desconocida</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>work zero set at %1 mm (machine)</source>
        <translation>cero de pieza fijado en %1 mm (máquina)</translation>
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
</TS>
