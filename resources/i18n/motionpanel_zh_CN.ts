<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN" sourcelanguage="en">
<context>
    <name>AboutDialog</name>
    <message>
        <location filename="../../widgets/about_dialog.py" line="+105"/>
        <source>About Motion Panel</source>
        <translation>关于 Motion Panel</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Motion Panel</source>
        <translation>Motion Panel</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Version %1</source>
        <translation>版本 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A desktop control panel for serial stepper-motor positioning stages.</source>
        <translation>用于串口步进电机定位平台的桌面控制面板。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>see LICENSE</source>
        <translation>见 LICENSE</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Licence: %1</source>
        <translation>许可证：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Components</source>
        <translation>组件</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>not installed</source>
        <translation>未安装</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1:</source>
        <translation>%1：</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&amp;Copy details</source>
        <translation>复制详细信息(&amp;C)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Copy the versions, e.g. for a bug report</source>
        <translation>复制各版本信息，例如用于提交错误报告</translation>
    </message>
</context>
<context>
    <name>ArcEntry</name>
    <message>
        <location filename="../../widgets/arc_entry.py" line="+274"/>
        <source>X of the arc&apos;s centre, in mm from home</source>
        <translation>圆弧圆心的 X 坐标，单位 mm，从原点起算</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y of the arc&apos;s centre, in mm from home</source>
        <translation>圆弧圆心的 Y 坐标，单位 mm，从原点起算</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Radius of the arc, in mm (more than 0)</source>
        <translation>圆弧半径，单位 mm（大于 0）</translation>
    </message>
    <message>
        <location line="-127"/>
        <source>Angle of the start point, 0 to 360°, counter-clockwise from +X seen from above</source>
        <translation>起点角度，0 至 360°，俯视时自 +X 方向逆时针计</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Angle of the end point, 0 to 360°, counter-clockwise from +X seen from above;
the same as the start angle: a full circle</source>
        <translation>终点角度，0 至 360°，俯视时自 +X 方向逆时针计；
与起点角度相同：整圆</translation>
    </message>
    <message>
        <location line="+120"/>
        <source>Z at the end of the arc, in mm; Z moves evenly from the current Z along the arc
(a helix when it differs)</source>
        <translation>圆弧终点处的 Z，单位 mm；Z 沿圆弧从当前 Z 匀速变化
（与当前 Z 不同时即为螺旋线）</translation>
    </message>
    <message>
        <location line="-96"/>
        <source>Centre X:</source>
        <translation>圆心 X：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Centre Y:</source>
        <translation>圆心 Y：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Radius:</source>
        <translation>半径：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start:</source>
        <translation>起始角：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>End:</source>
        <translation>终止角：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Final Z:</source>
        <translation>终点 Z：</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>CW</source>
        <translation>顺时针</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Clockwise seen from above: the angle decreases</source>
        <translation>俯视顺时针：角度递减</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CCW</source>
        <translation>逆时针</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Counter-clockwise seen from above: the angle increases</source>
        <translation>俯视逆时针：角度递增</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Preview</source>
        <translation>预览</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Draw the arc, dashed, in the position views</source>
        <translation>在位置视图中以虚线绘制圆弧</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Run arc</source>
        <translation>执行圆弧</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+189"/>
        <source>Move along the arc, from its start point to its end point</source>
        <translation>沿圆弧从起点移动到终点</translation>
    </message>
    <message>
        <location line="-181"/>
        <source>Why the arc cannot run</source>
        <translation>圆弧无法执行的原因</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>X of the arc&apos;s centre, in inches from home</source>
        <translation>圆弧圆心的 X 坐标，单位为英寸，从原点起算</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y of the arc&apos;s centre, in inches from home</source>
        <translation>圆弧圆心的 Y 坐标，单位为英寸，从原点起算</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Radius of the arc, in inches (more than 0)</source>
        <translation>圆弧半径，单位为英寸（大于 0）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Z at the end of the arc, in inches; Z moves evenly from the current Z along the arc
(a helix when it differs)</source>
        <translation>圆弧终点处的 Z，单位为英寸；Z 沿圆弧从当前 Z 匀速变化
（与当前 Z 不同时即为螺旋线）</translation>
    </message>
    <message>
        <location line="+148"/>
        <source>The radius must be more than 0 in.</source>
        <translation>半径必须大于 0 in。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The radius must be more than 0 mm.</source>
        <translation>半径必须大于 0 mm。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 %2 to %3 in (travel %4 to %5 in)</source>
        <translation>%1 %2 至 %3 in（行程 %4 至 %5 in）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 %2 in (travel %3 to %4 in)</source>
        <translation>%1 %2 in（行程 %3 至 %4 in）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 %2 to %3 mm (travel %4 to %5 mm)</source>
        <translation>%1 %2 至 %3 mm（行程 %4 至 %5 mm）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 %2 mm (travel %3 to %4 mm)</source>
        <translation>%1 %2 mm（行程 %3 至 %4 mm）</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>The arc leaves the travel limits: %1.</source>
        <translation>圆弧超出行程限位：%1。</translation>
    </message>
</context>
<context>
    <name>BridgeSession</name>
    <message>
        <location filename="../../app/window/device/bridge_session.py" line="+93"/>
        <source>the bridge failed: %1</source>
        <translation>桥接失败：%1</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>the bridge stopped</source>
        <translation>桥接已停止</translation>
    </message>
</context>
<context>
    <name>CompactReadout</name>
    <message>
        <location filename="../../widgets/compact_readout.py" line="+34"/>
        <source>Stage position from the device&apos;s home</source>
        <translation>平台位置（相对设备原点）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2)</source>
        <comment>the position&apos;s tip, then its status</comment>
        <translation>%1（%2）</translation>
    </message>
</context>
<context>
    <name>ConnectionBar</name>
    <message>
        <location filename="../../widgets/connection_bar.py" line="+32"/>
        <source>Disconnected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connecting…</source>
        <translation>正在连接…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connected</source>
        <translation>已连接</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Error</source>
        <translation>错误</translation>
    </message>
    <message>
        <location line="+93"/>
        <source>/dev/ttyUSB0, COM3 or a URL</source>
        <translation>/dev/ttyUSB0、COM3 或 URL</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Serial port, or any pyserial URL (e.g. sim://coxiris, socket://host:port, loop://)</source>
        <translation>串口，或任意 pyserial URL（例如 sim://coxiris、socket://host:port、loop://）</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Look for serial ports again</source>
        <translation>重新查找串口</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The language the device speaks</source>
        <translation>设备使用的通信协议</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Variant:</source>
        <translation>变体：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The wire variant of this protocol (packet format and rate)</source>
        <translation>此协议的线路变体（数据包格式和速率）</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Baud rate in bit/s (type any rate the device uses)</source>
        <translation>波特率，单位 bit/s（可输入设备使用的任意速率）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Bridge</source>
        <translation>桥接</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Bridge (snoop) mode: open the device&apos;s port and offer another program a pseudo-terminal; every byte is forwarded both ways unchanged and shown decoded here (motion controls are off while bridging)</source>
        <translation>桥接（监听）模式：打开设备的端口，并为另一个程序提供一个伪终端；每个字节都原样双向转发，并在此处解码显示（桥接期间运动控制不可用）</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+6"/>
        <location line="+225"/>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <location line="-225"/>
        <location line="+224"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location line="-224"/>
        <location line="+224"/>
        <source>Disconnect</source>
        <translation>断开</translation>
    </message>
    <message>
        <location line="-216"/>
        <source>Lines:</source>
        <translation>信号线：</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&amp;Port:</source>
        <translation>端口(&amp;P)：</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation type="vanished">端口：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Protocol:</source>
        <translation>协议：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Baud:</source>
        <translation>波特率：</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>No description for this port</source>
        <translation>此端口没有描述</translation>
    </message>
    <message>
        <location line="+111"/>
        <source>● %1: %2</source>
        <translation>● %1：%2</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Open the port and talk to the device</source>
        <translation>打开端口并与设备通信</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Close the connection</source>
        <translation>关闭连接</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>choose or type a port</source>
        <translation>请选择或输入端口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>choose a protocol</source>
        <translation>请选择协议</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the baud rate must be a positive whole number</source>
        <translation>波特率必须是正整数</translation>
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
        <translation>数据终端就绪</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Request To Send</source>
        <translation>请求发送</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear To Send</source>
        <translation>清除发送</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data Set Ready</source>
        <translation>数据设备就绪</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Carrier Detect</source>
        <translation>载波检测</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ring Indicator</source>
        <translation>振铃指示</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Break</source>
        <translation>中断信号</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Send a break: hold the transmit line low for %1 ms (the device sees a framing error; some boards take it as a reset or attention signal)</source>
        <translation>发送中断（Break）信号：将发送线保持低电平 %1 ms（设备会检测到帧错误；某些板卡将其视为复位或唤醒信号）</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>The serial port&apos;s control lines</source>
        <translation>串口的控制信号线</translation>
    </message>
    <message>
        <location line="+49"/>
        <location line="+16"/>
        <source>%1 (%2): not connected</source>
        <translation>%1（%2）：未连接</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>%1 (%2): this port cannot set %1</source>
        <translation>%1（%2）：此端口无法设置 %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (%2), driven by this computer: tick to assert it, untick to release it</source>
        <translation>%1（%2），由本机驱动：勾选以置位，取消勾选以释放</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>this port cannot report %1</source>
        <translation>此端口无法报告 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2), driven by the device: on</source>
        <translation>%1（%2），由设备驱动：开</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2), driven by the device: off</source>
        <translation>%1（%2），由设备驱动：关</translation>
    </message>
</context>
<context>
    <name>CoordinateEntry</name>
    <message>
        <location filename="../../widgets/coordinate_entry.py" line="+34"/>
        <source>Make the current position the new home (0, 0, 0)?
All coordinates will be measured from here from now on.</source>
        <translation>将当前位置设为新的原点 (0, 0, 0)？
此后所有坐标都将从这里起算。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Motion Panel</source>
        <translation>Motion Panel</translation>
    </message>
    <message>
        <source>%1:</source>
        <comment>an axis field&apos;s label</comment>
        <translation type="vanished">%1：</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Absolute</source>
        <translation>绝对</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>Go to the typed coordinates (mm from home)</source>
        <translation>移动到输入的坐标（从原点起算，单位 mm）</translation>
    </message>
    <message>
        <location line="-71"/>
        <source>Relative</source>
        <translation>相对</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>Move by the typed distances (mm) from where the stage is</source>
        <translation>从平台当前位置按输入的距离（mm）移动</translation>
    </message>
    <message>
        <location line="-63"/>
        <source>Machine</source>
        <translation>机床</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Work</source>
        <translation>工件</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>Which frame the typed coordinates are in: Machine (mm from the device&apos;s home) or Work (mm from the work zero); the device is always sent machine coordinates</source>
        <translation>输入坐标所用的坐标系：机床（从设备原点起算，单位 mm）或工件（从工件零点起算，单位 mm）；发送给设备的始终是机床坐标</translation>
    </message>
    <message>
        <location line="-58"/>
        <source>Go</source>
        <translation>移动</translation>
    </message>
    <message>
        <location line="-26"/>
        <source>&amp;%1:</source>
        <comment>an axis field&apos;s label; Alt+axis</comment>
        <translation>&amp;%1：</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Start the move (Enter in a field)</source>
        <translation>开始移动（在输入框中按 Enter）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Use current</source>
        <translation>取当前位置</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fill the fields with the current position</source>
        <translation>用当前位置填充各输入框</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Home</source>
        <translation>回原点</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Run the homing sequence</source>
        <translation>执行回原点流程</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Set Home</source>
        <translation>设为原点</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Make the current position the origin (asks first)</source>
        <translation>将当前位置设为原点（会先询问）</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+177"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location line="-177"/>
        <source>Stop the stage now</source>
        <translation>立即停止平台</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the stage now (Esc)</source>
        <translation>立即停止平台（Esc）</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Go to the typed coordinates (inches from home)</source>
        <translation>移动到输入的坐标（从原点起算，单位为英寸）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Move by the typed distances (inches) from where the stage is</source>
        <translation>从平台当前位置按输入的距离（英寸）移动</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Which frame the typed coordinates are in: Machine (inches from the device&apos;s home) or Work (inches from the work zero); the device is always sent machine coordinates, in mm</source>
        <translation>输入坐标所用的坐标系：机床（从设备原点起算，单位为英寸）或工件（从工件零点起算，单位为英寸）；发送给设备的始终是机床坐标，单位 mm</translation>
    </message>
    <message>
        <location line="+147"/>
        <source>Drop queued</source>
        <translation>清空队列</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1 distance to move, %2 to %3 in (%4)</source>
        <translation>%1 移动距离，%2 至 %3 in（%4）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 target coordinate, %2 to %3 in (%4)</source>
        <translation>%1 目标坐标，%2 至 %3 in（%4）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 target coordinate in the work frame, %2 to %3 in (%4)</source>
        <translation>%1 工件坐标系中的目标坐标，%2 至 %3 in（%4）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 distance to move, %2 to %3 mm (%4)</source>
        <translation>%1 移动距离，%2 至 %3 mm（%4）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 target coordinate, %2 to %3 mm (%4)</source>
        <translation>%1 目标坐标，%2 至 %3 mm（%4）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 target coordinate in the work frame, %2 to %3 mm (%4)</source>
        <translation>%1 工件坐标系中的目标坐标，%2 至 %3 mm（%4）</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>travel limits</source>
        <translation>行程限位</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no travel limits set</source>
        <translation>未设置行程限位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(this device has no such axis)</source>
        <translation>（此设备没有该轴）</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1; nothing sent</source>
        <translation>%1；未发送任何内容</translation>
    </message>
</context>
<context>
    <name>DerivedValues</name>
    <message>
        <location filename="../../widgets/parameter_table.py" line="+501"/>
        <source>Derived values</source>
        <translation>派生值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Computed from the values in the table, not read from the device</source>
        <translation>根据表中的值计算得出，并非从设备读取</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>a parameter</source>
        <translation>某个参数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>needs a value for %1</source>
        <translation>需要 %1 的值</translation>
    </message>
</context>
<context>
    <name>DeviceDocks</name>
    <message>
        <location filename="../../app/window/docks/device_docks.py" line="+93"/>
        <source>Not now: %1</source>
        <translation>暂不可用：%1</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>%1 on %2</source>
        <translation>%2 上的 %1</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>%1 to %2 mm on every axis (16-bit ticks)</source>
        <translation>各轴 %1 至 %2 mm（16 位计数）</translation>
    </message>
    <message>
        <source>program %1: %2 points, nothing sent yet</source>
        <translation type="vanished">程序 %1：%2 个点，尚未发送</translation>
    </message>
    <message>
        <source>program saved to %1 (%2 points)</source>
        <translation type="vanished">程序已保存到 %1（%2 个点）</translation>
    </message>
    <message>
        <source>the program stopped: %1</source>
        <translation type="vanished">程序已停止：%1</translation>
    </message>
    <message>
        <source>program %1 done: %2/%3 executed, %4 frames, %5 retransmission(s), %6 s</source>
        <translation type="vanished">程序 %1 完成：已执行 %2/%3，%4 帧，重传 %5 次，%6 s</translation>
    </message>
    <message>
        <source>program %1 stopped, the device&apos;s queue flushed: %2/%3 executed, %4 frames, %5 retransmission(s), %6 s</source>
        <translation type="vanished">程序 %1 已停止，设备队列已清空：已执行 %2/%3，%4 帧，重传 %5 次，%6 s</translation>
    </message>
</context>
<context>
    <name>DockLayout</name>
    <message>
        <location filename="../../app/window/layout/dock_layout.py" line="+16"/>
        <source>Stepper setup</source>
        <translation>步进电机设置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frame setup</source>
        <translation>机架设置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Program</source>
        <translation>程序</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Arc</source>
        <translation>圆弧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dwell</source>
        <translation>延时</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Travel limits</source>
        <translation>行程限位</translation>
    </message>
</context>
<context>
    <name>DwellEntry</name>
    <message>
        <location filename="../../widgets/dwell_entry.py" line="+28"/>
        <source>Dwell:</source>
        <translation>延时：</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>How long the device waits, 0 to %1 ms; press Enter or Dwell to send</source>
        <translation>设备等待的时长，0 至 %1 ms；按 Enter 或“延时”发送</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Dwell</source>
        <translation>延时</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Make the device wait this long before its next command</source>
        <translation>让设备在执行下一条命令前等待这段时间</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1; nothing sent</source>
        <translation>%1；未发送任何内容</translation>
    </message>
</context>
<context>
    <name>FirmataPanel</name>
    <message>
        <location filename="../../widgets/firmata_panel.py" line="+31"/>
        <source>version unknown</source>
        <translation>版本未知</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Full steps per revolution of the motor, 1 to %1 (e.g. 200)</source>
        <translation>电机每转整步数，1 至 %1（例如 200）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 pins</source>
        <translation>%1 个引脚</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>2 pins: a driver with step and direction inputs; 4 pins: the motor&apos;s four wires</source>
        <translation>2 个引脚：带脉冲和方向输入的驱动器；4 个引脚：电机的四根线</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>pin </source>
        <translation>引脚 </translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Motor steps per mm of travel (more than 0): converts mm and mm/s to steps</source>
        <translation>每毫米行程的电机步数（大于 0）：用于将 mm 和 mm/s 换算为步数</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The speed in mm/s and the motor speed it means, in revolutions per minute</source>
        <translation>以 mm/s 表示的速度及其对应的电机转速（每分钟转数）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Configure</source>
        <translation>配置</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Set up the stepper on the board with these settings</source>
        <translation>按这些设置在控制板上配置步进电机</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Library version</source>
        <translation>库版本</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ask the board for its stepper library&apos;s version</source>
        <translation>向控制板查询其步进电机库的版本</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The stepper library version the board reported</source>
        <translation>控制板报告的步进电机库版本</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Steps/rev:</source>
        <translation>每转步数：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Steps per mm:</source>
        <translation>每毫米步数：</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Pins:</source>
        <translation>引脚：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The board&apos;s pin numbers (0 to %1) wired to the motor</source>
        <translation>与电机相连的控制板引脚编号（0 至 %1）</translation>
    </message>
    <message>
        <location line="+111"/>
        <source>step</source>
        <translation>脉冲</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>motor wire</source>
        <translation>电机线</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pin %1 (%2), 0 to %3</source>
        <translation>引脚 %1（%2），0 至 %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not used</source>
        <translation>未使用</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+2"/>
        <source>speed: %1 mm/s = %2 rpm</source>
        <translation>速度：%1 mm/s = %2 rpm</translation>
    </message>
</context>
<context>
    <name>Jobs</name>
    <message>
        <location filename="../../app/window/device/jobs.py" line="+25"/>
        <source>move to (%1, %2, %3) mm</source>
        <translation>移动到 (%1, %2, %3) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>jog by (%1, %2, %3) %4</source>
        <translation>点动 (%1, %2, %3) %4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>relative move by (%1, %2, %3) %4</source>
        <translation>相对移动 (%1, %2, %3) %4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>go home</source>
        <translation>回原点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set home here</source>
        <translation>将此处设为原点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set speed %1 mm/s</source>
        <translation>设置速度 %1 mm/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set %1 = %2 %3</source>
        <translation>设置 %1 = %2 %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>arc around (%1, %2) mm, radius %3 mm, from %4° to %5° CCW</source>
        <translation>绕 (%1, %2) mm 走圆弧，半径 %3 mm，从 %4° 到 %5°，逆时针</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>arc around (%1, %2) mm, radius %3 mm, from %4° to %5° CW</source>
        <translation>绕 (%1, %2) mm 走圆弧，半径 %3 mm，从 %4° 到 %5°，顺时针</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dwell %1 ms</source>
        <translation>延时 %1 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set %1</source>
        <translation>设置 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>configure the stepper: %1 steps/rev on pins %2</source>
        <translation>配置步进电机：每转 %1 步，引脚 %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ask the stepper library version</source>
        <translation>查询步进电机库版本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>run %1 (%2 points)</source>
        <translation>运行 %1（%2 个点）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>run %1 (%2 lines)</source>
        <translation>运行 %1（%2 行）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>run %1 (%2 entities)</source>
        <translation>运行 %1（%2 个图元）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>run %1 (%2 elements)</source>
        <translation>运行 %1（%2 个元素）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>send &quot;%1&quot;</source>
        <translation>发送“%1”</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>refresh position and speed</source>
        <translation>刷新位置和速度</translation>
    </message>
</context>
<context>
    <name>JogPanel</name>
    <message>
        <location filename="../../widgets/jog_panel.py" line="+35"/>
        <source>Keys: ←/→ X, ↑/↓ Y, PgUp/PgDn Z, Shift ×10</source>
        <translation>按键：←/→ X，↑/↓ Y，PgUp/PgDn Z，Shift ×10</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Move the stage by one step; hold a button or key to keep stepping.
%1 (see the hint below for where the keys work).</source>
        <translation>将平台移动一步；按住按钮或按键可持续步进。
%1（按键在何处有效，见下方提示）。</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Step:</source>
        <translation>步长：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Distance of one jog</source>
        <translation>每次点动的距离</translation>
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
        <translation>每按一次点动 %1</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>%1 in</source>
        <translation>%1 in</translation>
    </message>
    <message>
        <location line="+131"/>
        <source>Any step size (%1 to %2 in)</source>
        <translation>任意步长（%1 至 %2 in）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Any step size (0.001 to 1000 mm)</source>
        <translation>任意步长（0.001 至 1000 mm）</translation>
    </message>
    <message>
        <location line="+174"/>
        <source>%1; no jog</source>
        <translation>%1；无法点动</translation>
    </message>
    <message>
        <location line="-256"/>
        <source>keys active</source>
        <translation>按键已启用</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>keys off: %1</source>
        <translation>按键已停用：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The jog keys work while this window is active and no menu, list, dialog or popup
is open, except when the focus is in a field that uses the arrow keys itself
(text and number fields, drop-down lists, the speed slider, the console).
Click the views or this panel to give the keys back to jogging.
Hold a key to keep stepping; Shift for a step ten times bigger.</source>
        <translation>当此窗口处于活动状态，且未打开任何菜单、列表、对话框或弹出窗口时，点动键有效；
但焦点位于自身使用方向键的控件中时除外
（文本框和数字框、下拉列表、速度滑块、控制台）。
点击视图或此面板，即可让按键恢复点动。
按住按键可持续步进；按住 Shift 则步长放大十倍。</translation>
    </message>
    <message>
        <location line="+103"/>
        <source>Jog %1 by %2 in (Shift: %3 in)</source>
        <translation>%1 轴点动 %2 in（Shift：%3 in）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Jog %1 by %2 mm (Shift: %3 mm)</source>
        <translation>%1 轴点动 %2 mm（Shift：%3 mm）</translation>
    </message>
</context>
<context>
    <name>KeyboardJog</name>
    <message>
        <location filename="../../app/window/keyboard_jog.py" line="+38"/>
        <source>a text field</source>
        <translation>文本框</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a number field</source>
        <translation>数字框</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a drop-down list</source>
        <translation>下拉列表</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a slider</source>
        <translation>滑块</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a list or text view</source>
        <translation>列表或文本视图</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a choice</source>
        <translation>单选项</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the menu bar</source>
        <translation>菜单栏</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a menu</source>
        <translation>菜单</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tabs</source>
        <translation>标签页</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>a menu or list is open</source>
        <translation>菜单或列表已打开</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a dialog is open</source>
        <translation>对话框已打开</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>another window is active</source>
        <translation>其他窗口处于活动状态</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the focus is in %1</source>
        <translation>焦点在%1中</translation>
    </message>
</context>
<context>
    <name>LogViewer</name>
    <message>
        <location filename="../../app/window/console/log_viewer.py" line="+48"/>
        <source>(undecoded)</source>
        <translation>（未解码）</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Open traffic log</source>
        <translation>打开通信日志</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Logs (*.log *.txt);;All files (*)</source>
        <translation>日志 (*.log *.txt);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Traffic log</source>
        <translation>通信日志</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Decode with this protocol (chosen from the log&apos;s connection note when it has one)</source>
        <translation>用此协议解码（若日志含连接说明，则据此选择）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Open…</source>
        <translation>打开…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open a Motion Panel log or a pyserial spy:// capture</source>
        <translation>打开 Motion Panel 日志或 pyserial spy:// 捕获文件</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no log open</source>
        <translation>未打开日志</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Close this log&apos;s window (Ctrl+W, Esc)</source>
        <translation>关闭此日志窗口（Ctrl+W、Esc）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Protocol:</source>
        <translation>协议：</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>reading %1…</source>
        <translation>正在读取 %1…</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>%1 — traffic log</source>
        <translation>%1 — 通信日志</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (%2): %3 lines, decoded as %4</source>
        <translation>%1（%2）：%3 行，按 %4 解码</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>, recognised from its traffic (the log names no protocol)</source>
        <translation>，根据其通信内容识别（日志未指明协议）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>; a simulator&apos;s record: TX and RX shown as the host saw them</source>
        <translation>；模拟器的记录：TX 和 RX 按主机一方所见显示</translation>
    </message>
</context>
<context>
    <name>MacroDock</name>
    <message>
        <location filename="../../app/window/docks/macro_dock.py" line="+30"/>
        <source>Motion Panel macros (*.json);;All files (*)</source>
        <translation>Motion Panel 宏 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Macros</source>
        <translation>宏</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Steps (one per line, each waits for the device): home · set-home · position · move X Y [Z] (mm) · jog DX DY [DZ] (mm) · speed V (mm/s) · raw TEXT (sent as typed, its reply awaited) · wait S (s, the panel pauses) · check · id · limits; and where the device has them: dwell MS (ms) · arc CX CY R START END --cw|--ccw · step RPM STEPS · status · stop · version.</source>
        <comment>the command words (home, move, --cw …) are typed as they are: keep them in English</comment>
        <translation>步骤（每行一个，每步都等待设备应答）：home · set-home · position · move X Y [Z] (mm) · jog DX DY [DZ] (mm) · speed V (mm/s) · raw TEXT（按输入原样发送，并等待其应答）· wait S（s，面板暂停）· check · id · limits；设备支持时还有：dwell MS (ms) · arc CX CY R START END --cw|--ccw · step RPM STEPS · status · stop · version。</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Macros (%1)</source>
        <translation>宏（%1）</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1; nothing sent</source>
        <translation>%1；未发送任何内容</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>macro %1: step %2/%3: %4</source>
        <translation>宏 %1：第 %2/%3 步：%4</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>choose a protocol first</source>
        <translation>请先选择协议</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a macro named %1 exists already</source>
        <translation>已存在名为 %1 的宏</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>macro %1 kept (%2 steps)</source>
        <translation>宏 %1 已保存（%2 步）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>macro %1 deleted</source>
        <translation>宏 %1 已删除</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 macros; at most %2</source>
        <translation>%1 个宏；最多 %2 个</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>macros not imported: %1</source>
        <translation>宏未导入：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>; %1 for other protocols left out</source>
        <translation>；略过 %1 个其他协议的宏</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>imported %1 macro(s) from %2%3</source>
        <translation>已从 %2 导入 %1 个宏%3</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>macros not exported: cannot write %1: %2</source>
        <translation>宏未导出：无法写入 %1：%2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>exported %1 macro(s) to %2</source>
        <translation>已导出 %1 个宏到 %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Import macros</source>
        <translation>导入宏</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Export macros</source>
        <translation>导出宏</translation>
    </message>
</context>
<context>
    <name>MacroEditor</name>
    <message>
        <location filename="../../widgets/macro_editor.py" line="+51"/>
        <source>Edit macro</source>
        <translation>编辑宏</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>New macro</source>
        <translation>新建宏</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The button&apos;s label: 1 to 40 characters</source>
        <translation>按钮上的文字：1 至 40 个字符</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>One step per line, as motionctl takes it: distances in mm, speeds in mm/s, waits in s. Each step waits for the device&apos;s reply before the next.</source>
        <translation>每行一个步骤，格式与 motionctl 相同：距离单位 mm，速度单位 mm/s，等待单位 s。每一步都等待设备应答后再执行下一步。</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Delete</source>
        <translation>删除</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Remove this macro</source>
        <translation>删除此宏</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Name:</source>
        <translation>名称(&amp;N)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Steps:</source>
        <translation>步骤(&amp;S)：</translation>
    </message>
</context>
<context>
    <name>MacroPanel</name>
    <message>
        <location filename="../../widgets/macro_panel.py" line="+37"/>
        <source>No macros yet: New… writes one, Import… reads a file.</source>
        <translation>还没有宏：用“新建…”编写，或用“导入…”从文件读取。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>New…</source>
        <translation>新建…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Write a new macro</source>
        <translation>编写新宏</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Edit</source>
        <translation>编辑</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Change or delete a macro</source>
        <translation>修改或删除宏</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Import…</source>
        <translation>导入…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add the macros of a file (JSON; data only, checked before any is kept)</source>
        <translation>添加文件中的宏（JSON；仅含数据，保存前先检查）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export…</source>
        <translation>导出…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Write this protocol&apos;s macros to a file</source>
        <translation>将此协议的宏写入文件</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Run %1:
%2</source>
        <translation>运行 %1：
%2</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Macros off: %1</source>
        <translation>宏不可用：%1</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <location filename="../../app/window/layout/fit_controls.py" line="+18"/>
        <source>%1 has no stop command: this drops the commands not yet sent; a move already under way on the device finishes (Esc)</source>
        <translation>%1 没有停止命令：此操作会丢弃尚未发送的命令；设备上已在进行的移动会继续完成（Esc）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Stop the stage now: halts the move under way and drops what is queued (Esc)</source>
        <translation>立即停止平台：中止正在进行的移动，并清空队列（Esc）</translation>
    </message>
    <message>
        <location filename="../../app/window/device/connection.py" line="+57"/>
        <source>simulated %1 device</source>
        <translation>模拟的 %1 设备</translation>
    </message>
    <message>
        <location filename="../../app/window/main_window.py" line="+101"/>
        <source>Motion Panel</source>
        <translation>Motion Panel</translation>
    </message>
    <message>
        <location filename="../../app/window/device/worker_link.py" line="+113"/>
        <source>no session log: %1</source>
        <translation>无会话日志：%1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>session log: %1</source>
        <translation>会话日志：%1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>no session log from now on</source>
        <translation>此后不再记录会话日志</translation>
    </message>
    <message>
        <location filename="../../app/window/main_window.py" line="+130"/>
        <source>Connection</source>
        <translation>连接</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Position</source>
        <translation>位置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jog</source>
        <translation>点动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Go to</source>
        <translation>定位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Console</source>
        <translation>控制台</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Parameters</source>
        <translation>参数</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Traffic timeline</source>
        <translation>通信时间线</translation>
    </message>
    <message>
        <location filename="../../app/window/menus.py" line="+26"/>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export traffic log…</source>
        <translation>导出通信日志(&amp;E)…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save every byte sent and received, with timestamps, to a text file</source>
        <translation>将收发的每个字节连同时间戳保存到文本文件</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Open log…</source>
        <translation>打开日志(&amp;O)…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Browse a traffic log (ours or a pyserial spy:// capture) decoded</source>
        <translation>浏览解码后的通信日志（本程序的日志或 pyserial spy:// 捕获文件）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Open the session &amp;log folder</source>
        <translation>打开会话日志文件夹(&amp;L)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Every byte of every session is kept there, one file a session</source>
        <translation>每次会话的每个字节都保存在那里，每次会话一个文件</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Motion</source>
        <translation>运动(&amp;M)</translation>
    </message>
    <message>
        <location filename="../../app/window/layout/fit_controls.py" line="+49"/>
        <location filename="../../app/window/menus.py" line="+1"/>
        <source>&amp;Stop</source>
        <translation>停止(&amp;S)</translation>
    </message>
    <message>
        <location filename="../../app/window/menus.py" line="+4"/>
        <source>&amp;Travel limits…</source>
        <translation>行程限位(&amp;T)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The box the stage may move in, for this device</source>
        <translation>此设备上平台允许移动的范围</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Reset views</source>
        <translation>重置视图(&amp;R)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Clear trail</source>
        <translation>清除轨迹(&amp;C)</translation>
    </message>
    <message>
        <location filename="../../app/window/device/connection.py" line="+76"/>
        <source>%1 names its protocol: connecting as %2</source>
        <translation>%1 已指明其协议：按 %2 连接</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>connecting to %1 (%2, %3 baud)</source>
        <translation>正在连接 %1（%2，%3 波特）</translation>
    </message>
    <message>
        <location line="+88"/>
        <source>bridge refused: %1</source>
        <translation>桥接被拒绝：%1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>bridge: %1</source>
        <translation>桥接：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>bridging %1 to %2</source>
        <translation>正在将 %1 桥接到 %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bridge: another program can open %1; every byte goes to %2</source>
        <translation>桥接：其他程序可打开 %1；每个字节都会转发到 %2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>bridge ended: %1</source>
        <translation>桥接已结束：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>bridge closed</source>
        <translation>桥接已关闭</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>connection error: %1</source>
        <translation>连接错误：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+9"/>
        <source>disconnected</source>
        <translation>已断开连接</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>disconnected from %1 on %2</source>
        <translation>已断开通过 %2 与 %1 的连接</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>connected to %1 on %2</source>
        <translation>已通过 %2 连接到 %1</translation>
    </message>
    <message>
        <location filename="../../app/window/device/machine_state.py" line="+38"/>
        <source>home set: the position is counted from here</source>
        <translation>已设为原点：位置从此处开始计数</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>an absolute point reached: the position is counted from here</source>
        <translation>已到达绝对点：位置从此处开始计数</translation>
    </message>
    <message>
        <location line="+53"/>
        <location line="+116"/>
        <source>the position is unknown: this device cannot report it; home it or set home</source>
        <translation>位置未知：此设备无法报告其位置；请回原点或设为原点</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>connected again to %1: the position was read again</source>
        <translation>已重新连接到 %1：已重新读取位置</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the device cannot be asked where it is: it goes on from (%1, %2, %3) mm, where it was left on this port (kept, not measured)</source>
        <translation>无法查询设备的位置：从 (%1, %2, %3) mm 继续，即上次在此端口停留的位置（已保存，非实测）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>position unknown: the device cannot be asked; Home or Set Home to start counting</source>
        <translation>位置未知：无法查询设备；请“回原点”或“设为原点”以开始计数</translation>
    </message>
    <message>
        <location filename="../../app/window/layout/fit_controls.py" line="-41"/>
        <source>the device</source>
        <translation>该设备</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Go to the home position (0, 0, 0)</source>
        <translation>移动到原点位置 (0, 0, 0)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Make the current position the origin (asks first)</source>
        <translation>将当前位置设为原点（会先询问）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Restart the panel&apos;s count of the position here (asks first); %1 has no set-home command, so nothing is sent</source>
        <translation>在此处重新开始面板的位置计数（会先询问）；%1 没有设置原点命令，因此不会发送任何内容</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>&amp;Drop queued commands</source>
        <translation>清空命令队列(&amp;D)</translation>
    </message>
    <message>
        <location filename="../../app/window/device/connection.py" line="+58"/>
        <source>port %1 appeared</source>
        <translation>端口 %1 已出现</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>reconnecting to %1</source>
        <translation>正在重新连接到 %1</translation>
    </message>
    <message>
        <location line="-296"/>
        <source>port %1 disappeared</source>
        <translation>端口 %1 已消失</translation>
    </message>
    <message>
        <location line="+309"/>
        <source>%1 on %2</source>
        <translation>%2 上的 %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>travel limits: %1</source>
        <translation>行程限位：%1</translation>
    </message>
    <message>
        <location filename="../../app/window/device/job_desk.py" line="+115"/>
        <source>not connected: %1 not sent</source>
        <translation>未连接：%1 未发送</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 refused: the position is unknown, so the program&apos;s coordinates would not be where it goes; Home or Set Home first</source>
        <translation>%1 被拒绝：位置未知，程序的坐标将不是它实际去的地方；请先执行“回原点”或“设为原点”</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 refused: the position is unknown and this device moves only to absolute targets, so it would go elsewhere; Set Home, Home or Go to first</source>
        <translation>%1 被拒绝：位置未知，且此设备只移动到绝对目标，因此会去到别处；请先执行“设为原点”、“回原点”或“定位”</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 refused: %2 is under way; wait for its end or press Stop</source>
        <translation>%1 被拒绝：%2 正在进行；请等待其结束或按“停止”</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>motion controls are off until %1 ends (Stop ends it now)</source>
        <translation>%1 结束前运动控制不可用（按“停止”可立即结束）</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1 is under way</source>
        <translation>%1 正在进行</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>jog refused: %1</source>
        <translation>点动被拒绝：%1</translation>
    </message>
    <message>
        <location line="+92"/>
        <source>Send unchecked bytes?</source>
        <translation>发送未经检查的字节？</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>These bytes cannot be read as a command (%1), so they cannot be checked against the travel limits (%2): they might move the stage outside them.

Send them anyway?</source>
        <translation>这些字节无法解读为命令（%1），因此无法对照行程限位（%2）进行检查：它们可能使平台移出限位范围。

仍要发送吗？</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>not sent: the bytes could not be checked against the travel limits</source>
        <translation>未发送：无法对照行程限位检查这些字节</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>stopping the macro under way</source>
        <translation>正在停止执行中的宏</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>stopping the move under way</source>
        <translation>正在停止进行中的移动</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>nothing queued; the move under way finishes</source>
        <translation>队列为空；进行中的移动会继续完成</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>stopped: %1 command(s) not sent: %2</source>
        <translation>已停止：%1 条命令未发送：%2</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../../app/window/device/machine_state.py" line="+65"/>
        <source>new home: the trail is shifted by (%1, %2, %3) mm</source>
        <translation>新原点：轨迹已平移 (%1, %2, %3) mm</translation>
    </message>
    <message>
        <location line="-147"/>
        <source>the device reported an error: %1</source>
        <translation>设备报告错误：%1</translation>
    </message>
    <message>
        <location filename="../../app/window/device/connection.py" line="-125"/>
        <location filename="../../app/window/device/machine_state.py" line="+5"/>
        <source>device: %1</source>
        <translation>设备：%1</translation>
    </message>
    <message>
        <location filename="../../app/window/device/job_desk.py" line="-11"/>
        <source>%1 failed: %2</source>
        <translation>%1 失败：%2</translation>
    </message>
    <message>
        <location filename="../../app/window/device/machine_state.py" line="-118"/>
        <source>home confirmed: the position is counted from here</source>
        <translation>原点已确认：位置从此处开始计数</translation>
    </message>
    <message>
        <location line="+204"/>
        <source>position unknown: the device cannot be asked and its frames carry absolute targets, so a jog is refused; Set Home where the stage stands, Home, or Go to an absolute point first</source>
        <translation>位置未知：无法查询设备，且其帧携带的是绝对目标，因此点动被拒绝；请先在平台当前所在处“设为原点”、“回原点”，或“定位”到一个绝对点</translation>
    </message>
    <message>
        <location line="+206"/>
        <source>speed %1 mm/s reads back as %2 mm/s (the device rounds)</source>
        <translation>速度 %1 mm/s 回读为 %2 mm/s（设备会取整）</translation>
    </message>
    <message>
        <location filename="../../app/window/layout/arrangements.py" line="+93"/>
        <source>&amp;Operate</source>
        <translation>操作(&amp;P)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Set up</source>
        <translation>配置(&amp;U)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Traffic</source>
        <translation>通信(&amp;A)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Jog, go to and watch the stage: the views large</source>
        <translation>点动、定位并观察平台：视图放大显示</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The device&apos;s parameters and setup panels, and macros</source>
        <translation>设备的参数、设置面板以及宏</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The traffic console and its timeline, full width</source>
        <translation>通信控制台及其时间线，全宽显示</translation>
    </message>
    <message>
        <location filename="../../app/window/layout/layouts.py" line="+112"/>
        <source>Reset &amp;layout</source>
        <translation>重置布局(&amp;Y)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Put the docks of this layout back as they were at first</source>
        <translation>将此布局中的停靠窗口恢复到最初的位置</translation>
    </message>
    <message>
        <location line="+274"/>
        <source>this device has parameters: %1 for Set up</source>
        <translation>此设备有参数：按 %1 切换到“配置”</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>this device has a setup panel: %1 for Set up</source>
        <translation>此设备有设置面板：按 %1 切换到“配置”</translation>
    </message>
    <message>
        <location filename="../../app/window/device/program_pause.py" line="+22"/>
        <source>paused: nothing more is sent; the move under way finishes (this device has no feed hold)</source>
        <translation>已暂停：不再发送任何内容；进行中的移动会继续完成（此设备没有进给保持功能）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>resumed: sending the program again</source>
        <translation>已继续：重新开始发送程序</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>paused: nothing more is sent; the device still holds %1 move(s) and runs them (its protocol has no feed hold): it stands still in about %2 s; Stop flushes them now</source>
        <translation>已暂停：不再发送任何内容；设备仍保有 %1 个移动并会执行完（其协议没有进给保持功能）：约 %2 s 后静止；按“停止”可立即清除这些移动</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>paused: the device has run what it held; the stage stands still</source>
        <translation>已暂停：设备已执行完其保有的移动；平台已静止</translation>
    </message>
</context>
<context>
    <name>NumberField</name>
    <message>
        <location filename="../../widgets/_number_field.py" line="+35"/>
        <source>a number is needed, %1 to %2%3</source>
        <translation>需要输入数字，%1 至 %2%3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1%2 is not a whole number</source>
        <translation>%1%2 不是整数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>“%1” is not a number (%2 to %3%4)</source>
        <translation>“%1”不是数字（%2 至 %3%4）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1%4 is outside %2 to %3%4</source>
        <translation>%1%4 超出 %2 至 %3%4 的范围</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1%2 has more than %3 decimals</source>
        <translation>%1%2 的小数位数超过 %3 位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1; cleared when the units changed to %2</source>
        <translation>%1；单位改为 %2 时已清除</translation>
    </message>
</context>
<context>
    <name>ParameterDock</name>
    <message>
        <location filename="../../app/window/docks/parameter_dock.py" line="+34"/>
        <source>the device now holds %1: the firmware forces it after every set</source>
        <translation>设备当前值为 %1：每次设置后固件都会强制使用该值</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>steps</source>
        <translation>步</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>Parameters</source>
        <translation>参数</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>Parameters (%1)</source>
        <translation>参数（%1）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 on %2</source>
        <translation>%2 上的 %1</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>parameter writing cancelled: %1 not sent</source>
        <translation>参数写入已取消：%1 未发送</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>not sent</source>
        <translation>未发送</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>recomputed by the firmware at the last move</source>
        <translation>固件在上次移动时重新计算</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the device did not answer</source>
        <translation>设备无应答</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>connect to a device with parameters first</source>
        <translation>请先连接带参数的设备</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>loaded %1 values from %2; nothing sent (Write changed sends them)</source>
        <translation>已从 %2 加载 %1 个值；尚未发送（“写入更改”会发送它们）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>left out, computed by the firmware: %1</source>
        <translation>已略过（由固件计算）：%1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>saved %1 values to %2</source>
        <translation>已将 %1 个值保存到 %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (firmware outputs are never saved)</source>
        <translation>%1（固件输出参数从不保存）</translation>
    </message>
</context>
<context>
    <name>ParameterEditor</name>
    <message>
        <location filename="../../widgets/parameter_editor.py" line="+49"/>
        <source>Parameter profiles (*.toml);;All files (*)</source>
        <translation>参数配置文件 (*.toml);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>The device cannot be read back: this compares with what this panel last wrote</source>
        <translation>设备无法回读：此处与本面板上次写入的值比较</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Packets written so far; each is confirmed before the next</source>
        <translation>已写入的数据包；每个数据包确认后才发送下一个</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Write selected</source>
        <translation>写入所选</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write the values of the selected rows</source>
        <translation>写入所选行的值</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Write all</source>
        <translation>全部写入</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write every value in the table, one packet each</source>
        <translation>写入表中的每个值，每个值一个数据包</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Write changed</source>
        <translation>写入更改</translation>
    </message>
    <message>
        <source>Write the values marked • (not yet written)</source>
        <translation type="vanished">写入标有 • 的值（尚未写入）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop writing after the packet under way</source>
        <translation>当前数据包完成后停止写入</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Load profile…</source>
        <translation>加载配置…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fill the table from a file</source>
        <translation>从文件填充表格</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save profile…</source>
        <translation>保存配置…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Save the values to a file</source>
        <translation>将这些值保存到文件</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Not loaded: %1</source>
        <translation>未加载：%1</translation>
    </message>
    <message>
        <location line="+151"/>
        <source>nothing sent</source>
        <translation>未发送任何内容</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write finished: %1</source>
        <translation>写入完成：%1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 / %2 packets, about %3 left</source>
        <translation>%1 / %2 个数据包，约剩 %3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no row selected</source>
        <translation>未选择任何行</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the table has no values</source>
        <translation>表中没有值</translation>
    </message>
    <message>
        <source>nothing differs</source>
        <translation type="vanished">没有不同的值</translation>
    </message>
    <message>
        <location line="-238"/>
        <source>Write the input values marked • (they differ from what the device holds); firmware outputs are not written by it</source>
        <translation>写入标有 • 的输入值（它们与设备当前的值不同）；此按钮不写入固件输出参数</translation>
    </message>
    <message>
        <location line="+247"/>
        <source>no input differs</source>
        <translation>没有不同的输入值</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Nothing to write: %1</source>
        <translation>无可写入内容：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Writing 1 value</source>
        <translation>正在写入 1 个值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writing %1 values</source>
        <translation>正在写入 %1 个值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no value, not written: %1</source>
        <translation>无值，未写入：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>computed by the firmware, which may replace them: %1</source>
        <translation>由固件计算，固件可能会替换写入的值：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Warning: %1</source>
        <translation>警告：%1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cancelling: the packet under way finishes, the rest are not sent</source>
        <translation>正在取消：当前数据包会完成，其余的不再发送</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Save parameter profile</source>
        <translation>保存参数配置</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Load parameter profile</source>
        <translation>加载参数配置</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>No parameters</source>
        <translation>无参数</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No values yet: load a profile or type them into the Value column</source>
        <translation>尚无值：请加载配置，或在“值”列中输入</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>1 value differs from what was last written to this device (marked •)</source>
        <translation>有 1 个值与上次写入此设备的值不同（标有 •）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 values differ from what was last written to this device (marked •)</source>
        <translation>有 %1 个值与上次写入此设备的值不同（标有 •）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Every value is what was last written to this device</source>
        <translation>所有值均与上次写入此设备的值相同</translation>
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
        <translation>名称</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Last written</source>
        <translation>上次写入</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Kind</source>
        <translation>类型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Description</source>
        <translation>说明</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Status</source>
        <translation>状态</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The value to write, in the unit beside it (double-click, F2, Enter or type)</source>
        <translation>要写入的值，单位见旁列（双击、按 F2、Enter 或直接输入）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>What this panel last wrote to the device (the device cannot be read back)</source>
        <translation>本面板上次写入设备的值（设备无法回读）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>input: set by you; output: computed by the firmware</source>
        <translation>输入：由您设置；输出：由固件计算</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The outcome of the last write of this parameter</source>
        <translation>此参数上次写入的结果</translation>
    </message>
    <message>
        <location line="+92"/>
        <source>%1 (computed)</source>
        <translation>%1（计算值）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 (power-on)</source>
        <translation>%1（上电值）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>output</source>
        <translation>输出</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>input</source>
        <translation>输入</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Input: set by you and written to the device</source>
        <translation>输入：由您设置并写入设备</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: never written to this device from this panel; it holds %2 from power-on</source>
        <translation>%1：从未通过本面板写入此设备；其值为上电时的 %2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: never written to this device from this panel</source>
        <translation>%1：从未通过本面板写入此设备</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the device holds %2, computed by its firmware %3</source>
        <translation>%1：设备当前值为 %2，由其固件%3计算得出</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: last written %2</source>
        <translation>%1：上次写入 %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Allowed: %1</source>
        <translation>允许范围：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Value: %1</source>
        <translation>值：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>• Differs from what was last written to this device</source>
        <translation>• 与上次写入此设备的值不同</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>%1: no such parameter</source>
        <translation>%1：无此参数</translation>
    </message>
</context>
<context>
    <name>ParameterTableView</name>
    <message>
        <location line="+185"/>
        <source>Double-click a value, or select a row and press Enter or type, to edit</source>
        <translation>双击某个值，或选中一行后按 Enter 或直接输入，即可编辑</translation>
    </message>
</context>
<context>
    <name>ParameterValues</name>
    <message>
        <location filename="../../widgets/parameter_values.py" line="+40"/>
        <source>not written</source>
        <translation>未写入</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pending</source>
        <translation>等待中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>confirmed</source>
        <translation>已确认</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error</source>
        <translation>错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timed out</source>
        <translation>超时</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>after the last set</source>
        <translation>在上次设置后</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>at the last move</source>
        <translation>在上次移动时</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Output: computed by the firmware. Writing it is allowed, but the firmware may replace what is written.</source>
        <translation>输出：由固件计算。允许写入，但固件可能会替换写入的值。</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1 to %2, whole numbers</source>
        <translation>%1 至 %2，整数</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 to %2 in steps of %3</source>
        <translation>%1 至 %2，步进 %3</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1: %2 refused (%3): %4</source>
        <translation>%1：%2 被拒绝（%3）：允许 %4</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>empty</source>
        <translation>为空</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>use a point for decimals</source>
        <translation>请用点号（.）作小数点</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not a number</source>
        <translation>不是数字</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>not a finite number</source>
        <translation>不是有限数</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>below the minimum</source>
        <translation>低于最小值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>above the maximum</source>
        <translation>高于最大值</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not a multiple of %1</source>
        <translation>不是 %1 的整数倍</translation>
    </message>
</context>
<context>
    <name>PiFramePanel</name>
    <message>
        <location filename="../../widgets/piframe_panel.py" line="+17"/>
        <source>DTR on</source>
        <translation>DTR 开</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DTR off</source>
        <translation>DTR 关</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DTR unknown</source>
        <translation>DTR 未知</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Encoder ticks per mm of travel (more than 0): converts the frame&apos;s ticks to mm</source>
        <translation>每毫米行程的编码器计数（大于 0）：用于将机架的计数换算为 mm</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The state of the serial DTR line, which powers the frame</source>
        <translation>串口 DTR 线的状态，该线为机架供电</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The range the frame can reach, from its travel and ticks/mm</source>
        <translation>机架可到达的范围，由其行程和每毫米计数得出</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Ticks per mm:</source>
        <translation>每毫米计数：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DTR:</source>
        <translation>DTR：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reachable:</source>
        <translation>可达范围：</translation>
    </message>
</context>
<context>
    <name>PortWatcher</name>
    <message>
        <location filename="../../app/window/device/ports.py" line="+22"/>
        <source>serial port</source>
        <translation>串口</translation>
    </message>
</context>
<context>
    <name>PositionReadout</name>
    <message>
        <location filename="../../widgets/position_readout.py" line="+26"/>
        <source>commanded, not measured</source>
        <translation>指令值，非实测</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>commanded, move confirmed</source>
        <translation>指令值，移动已确认</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This device does not report its position: the numbers are where it was told to go.</source>
        <translation>此设备不报告其位置：显示的数值是指令要求它到达的位置。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Where the device was told to go, and its reply said the move ended there; not read back (a device that can report its position is asked again when idle).</source>
        <translation>设备被指令到达的位置，其应答表明移动已在此结束；并非回读值（能报告位置的设备会在空闲时再次查询）。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>position unknown: the device cannot be asked; Home or Set Home to start counting</source>
        <translation>位置未知：无法查询设备；请“回原点”或“设为原点”以开始计数</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>position unknown: the link failed or the device restarted, and it cannot report where it is; home it or set home</source>
        <translation>位置未知：连接故障或设备已重启，且设备无法报告其位置；请回原点或设为原点</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>estimated from the speed: the device cannot be asked while it moves</source>
        <translation>根据速度估算：设备移动时无法查询</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>estimated when the link was lost, during a move: somewhere between its start and its target; not connected</source>
        <translation>在移动中连接断开时估算：位于移动起点与目标之间的某处；未连接</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>bridging: no position seen in the bridged traffic yet (the panel asks nothing)</source>
        <translation>桥接中：桥接的通信中尚未出现位置（面板不进行任何查询）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>observed in the bridged traffic: the device reported this position to the other program</source>
        <translation>从桥接通信中观察到：设备向另一个程序报告了此位置</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>observed in the bridged traffic: the target of a move the other program sent, not confirmed by the device</source>
        <translation>从桥接通信中观察到：另一个程序发送的移动目标，未经设备确认</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>last known position: not connected</source>
        <translation>最后已知位置：未连接</translation>
    </message>
    <message>
        <source>Stage position in mm: from the device&apos;s home, and from the work zero</source>
        <translation type="vanished">平台位置（mm）：相对设备原点，以及相对工件零点</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>Machine</source>
        <translation>机床</translation>
    </message>
    <message>
        <source>Millimetres from the device&apos;s home (its origin)</source>
        <translation type="vanished">相对设备原点（其坐标原点）的毫米数</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Work</source>
        <translation>工件</translation>
    </message>
    <message>
        <source>Millimetres from the work zero the panel keeps (the device is not told)</source>
        <translation type="vanished">相对面板所记录工件零点的毫米数（不通知设备）</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Distances from the device&apos;s home (its origin)</source>
        <translation>相对设备原点的距离（其坐标原点）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Distances from the work zero the panel keeps (the device is not told)</source>
        <translation>相对面板保存的工件零点的距离（不告知设备）</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Zero %1</source>
        <translation>%1 清零</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Make the current %1 the work zero (0 mm in the work frame); the device is not told, and its home stays where it is</source>
        <translation>将当前 %1 设为工件零点（工件坐标系中的 0 mm）；不通知设备，设备原点保持不变</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Zero all</source>
        <translation>全部清零</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Make the current position the work zero</source>
        <translation>将当前位置设为工件零点</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Clear zero</source>
        <translation>清除零点</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Put the work zero back at the device&apos;s home (work = machine)</source>
        <translation>将工件零点恢复到设备原点（工件坐标 = 机床坐标）</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>The stage is outside the travel limits set for this device: only moves that bring it closer to them are sent, until it is back inside</source>
        <translation>平台位于为此设备设置的行程限位之外：在回到限位内之前，只会发送使其更接近限位范围的移动</translation>
    </message>
    <message>
        <location line="+121"/>
        <source>outside the travel limits: %1</source>
        <translation>超出行程限位：%1</translation>
    </message>
    <message>
        <location line="+101"/>
        <source>millimetres</source>
        <translation>毫米</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>inches</source>
        <translation>英寸</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stage position in %1: from the device&apos;s home, and from the work zero</source>
        <translation>平台位置（%1）：相对设备原点，以及相对工件零点</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>This device has no %1 axis</source>
        <translation>此设备没有 %1 轴</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Position unknown</source>
        <translation>位置未知</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 position in %2 from the device&apos;s home</source>
        <translation>%1 位置，相对设备原点，单位为%2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 position in %2 from the work zero</source>
        <translation>%1 位置，相对工件零点，单位为%2</translation>
    </message>
    <message>
        <source>%1 position in mm from the device&apos;s home</source>
        <translation type="vanished">%1 位置，相对设备原点，单位 mm</translation>
    </message>
    <message>
        <source>%1 position in mm from the work zero</source>
        <translation type="vanished">%1 位置，相对工件零点，单位 mm</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>work zero: home</source>
        <translation>工件零点：原点</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>work zero at (%1) %2 (machine)</source>
        <translation>工件零点位于 (%1) %2（机床坐标）</translation>
    </message>
    <message>
        <source>work zero at %1 mm (machine)</source>
        <translation type="vanished">工件零点位于 %1 mm（机床坐标）</translation>
    </message>
</context>
<context>
    <name>PositionView2D</name>
    <message>
        <location filename="../../widgets/view2d/xy_plot.py" line="+27"/>
        <source>Stage seen from above: trail, current position (dot; hollow when estimated), target (+), travel limits (dashed)</source>
        <translation>俯视平台：轨迹、当前位置（圆点；估算时为空心）、目标（+）、行程限位（虚线）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>XY (from above)</source>
        <translation>XY（俯视）</translation>
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
        <translation>X、Y、Z 随时间的变化；虚线：目标</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Position against time</source>
        <translation>位置随时间的变化</translation>
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
        <translation>时间（s，0 = 最新采样）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>t (s)</source>
        <translation>t (s)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>position (in)</source>
        <translation>位置 (in)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>in</source>
        <translation>in</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position (mm)</source>
        <translation>位置 (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <location line="-68"/>
        <source>Clear trail</source>
        <translation>清除轨迹</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Forget the path so far (the current position stays)</source>
        <translation>清除目前为止的路径（保留当前位置）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reset view</source>
        <translation>重置视图</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Zoom both plots to fit the data again</source>
        <translation>重新缩放两幅图以适应数据</translation>
    </message>
</context>
<context>
    <name>PositionView3D</name>
    <message>
        <location filename="../../widgets/view3d/navigation.py" line="+19"/>
        <source>Top</source>
        <translation>俯视</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>View from above (X right, Y up)</source>
        <translation>从上方观察（X 向右，Y 向上）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Front</source>
        <translation>前视</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>View from the front (X right, Z up)</source>
        <translation>从前方观察（X 向右，Z 向上）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Side</source>
        <translation>侧视</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>View from the side (Y right, Z up)</source>
        <translation>从侧面观察（Y 向右，Z 向上）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Iso</source>
        <translation>等轴</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>View from above at an angle</source>
        <translation>从斜上方观察</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Fit</source>
        <translation>适应</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zoom to the trail, the target and the workspace</source>
        <translation>缩放以显示轨迹、目标和工作区</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Follow</source>
        <translation>跟随</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep the camera on the current position</source>
        <translation>使视角始终对准当前位置</translation>
    </message>
    <message>
        <location filename="../../widgets/view3d/notice.py" line="+15"/>
        <source>Needs OpenGL 2.1 or newer (e.g. Mesa) on a display; see the README.</source>
        <translation>需要在有显示器的环境中提供 OpenGL 2.1 或更高版本（例如 Mesa）；请参阅 README。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>3D view unavailable: OpenGL could not be initialised.
(%1)
The 2D view shows the same positions.</source>
        <translation>3D 视图不可用：无法初始化 OpenGL。
（%1）
2D 视图显示相同的位置。</translation>
    </message>
    <message>
        <location filename="../../widgets/position_view_3d.py" line="+109"/>
        <source>Drag to rotate, wheel to zoom, middle-drag to pan</source>
        <translation>拖动旋转，滚轮缩放，中键拖动平移</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>grid %1 in</source>
        <translation>网格 %1 in</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>grid %1 mm</source>
        <translation>网格 %1 mm</translation>
    </message>
</context>
<context>
    <name>Preferences</name>
    <message>
        <location filename="../../app/window/preferences.py" line="+67"/>
        <source>Stop (Motion menu)</source>
        <translation>停止（运动菜单）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the console&apos;s next match</source>
        <translation>控制台中的下一个匹配项</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>moving the focus</source>
        <translation>移动焦点</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>connecting and sending</source>
        <translation>连接和发送</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pressing the focused button</source>
        <translation>按下当前焦点按钮</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>Poll while moving</source>
        <translation>移动时轮询</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Poll when idle</source>
        <translation>空闲时轮询</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Console lines kept</source>
        <translation>控制台保留行数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lines</source>
        <translation>行</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Session log</source>
        <translation>会话日志</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Session log folder</source>
        <translation>会话日志文件夹</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Units shown</source>
        <translation>显示单位</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Decimals shown</source>
        <translation>显示小数位数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>decimals</source>
        <translation>位小数</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Clamp moves to the limits</source>
        <translation>将移动限制在限位内</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>smaller step</source>
        <translation>较小步长</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>larger step</source>
        <translation>较大步长</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Theme</source>
        <translation>主题</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Language</source>
        <translation>语言</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Jog key %1</source>
        <translation>点动键 %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 to %2 %3</source>
        <translation>%1 至 %2 %3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: %2 lines is out of range: 0 (keep every line) or %3</source>
        <translation>%1：%2 行超出范围：应为 0（保留所有行）或 %3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2 is out of range: -1 (as the device resolves) or %3</source>
        <translation>%1：%2 超出范围：应为 -1（按设备分辨率）或 %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2 %3 is out of range (%4)</source>
        <translation>%1：%2 %3 超出范围（%4）</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>it must be an absolute path</source>
        <translation>必须是绝对路径</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>it does not exist</source>
        <translation>该路径不存在</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>it is not a folder</source>
        <translation>不是文件夹</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>it is not writable</source>
        <translation>不可写入</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>it must be a single key</source>
        <translation>必须是单个按键</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>it is not a key the panel can use</source>
        <translation>面板无法使用此按键</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no Shift, Ctrl, Alt or Meta: Shift makes the step ten times bigger</source>
        <translation>不能含 Shift、Ctrl、Alt 或 Meta：Shift 用于将步长放大十倍</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the window uses it for %1</source>
        <translation>窗口已将其用于%1</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1: choose a key</source>
        <translation>%1：请选择一个按键</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: %2 cannot be used: %3</source>
        <translation>%1：%2 无法使用：%3</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: %2 is already %3</source>
        <translation>%1：%2 已用作%3</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1: %2: %3</source>
        <translation>%1：%2：%3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: %2 is not one of %3</source>
        <translation>%1：%2 不是以下之一：%3</translation>
    </message>
</context>
<context>
    <name>ProgramDock</name>
    <message>
        <location filename="../../app/window/docks/program_dock.py" line="+181"/>
        <source>program %1 refused: %2</source>
        <translation>程序 %1 被拒绝：%2</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>only programs of points (CSV, JSON) are saved as JSON</source>
        <translation>只有由点组成的程序（CSV、JSON）才能保存为 JSON</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>program %1 cannot run: %2</source>
        <translation>程序 %1 无法运行：%2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>program %1: %2 segments, nothing sent yet</source>
        <translation>程序 %1：%2 段，尚未发送</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>the program has no moves</source>
        <translation>程序中没有移动</translation>
    </message>
    <message>
        <location line="+93"/>
        <source>program saved to %1 (%2 points)</source>
        <translation>程序已保存到 %1（%2 个点）</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>the program stopped: %1</source>
        <translation>程序已停止：%1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>program %1 done: %2/%3 executed in %4 s</source>
        <translation>程序 %1 完成：已执行 %2/%3，用时 %4 s</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>program %1 stopped: %2/%3 executed in %4 s</source>
        <translation>程序 %1 已停止：已执行 %2/%3，用时 %4 s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1; %2 frames, %3 retransmission(s)</source>
        <translation>%1；%2 帧，重传 %3 次</translation>
    </message>
</context>
<context>
    <name>ProgramPanel</name>
    <message>
        <source>Programs (*.csv *.json);;All files (*)</source>
        <translation type="vanished">程序 (*.csv *.json);;所有文件 (*)</translation>
    </message>
    <message>
        <location filename="../../widgets/program_panel.py" line="+39"/>
        <source>no program loaded</source>
        <translation>未加载程序</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation type="vanished">加载…</translation>
    </message>
    <message>
        <source>Load a program: CSV with x,y,z,speed (mm, mm/s) or JSON</source>
        <translation type="vanished">加载程序：含 x,y,z,speed 列的 CSV（mm、mm/s）或 JSON</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Save…</source>
        <translation>保存…</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Save the loaded program as JSON (x, y, z, speed per point)</source>
        <translation>将已加载的程序保存为 JSON（每个点含 x, y, z, speed）</translation>
    </message>
    <message>
        <source>Run</source>
        <translation type="vanished">运行</translation>
    </message>
    <message>
        <source>Stream the program to the device, 7 moves a frame</source>
        <translation type="vanished">将程序流式发送到设备，每帧 7 个移动</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="vanished">暂停</translation>
    </message>
    <message>
        <source>Send nothing more until Resume (queued moves go on)</source>
        <translation type="vanished">在“继续”之前不再发送（已排队的移动照常执行）</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="vanished">停止</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>&amp;Load…</source>
        <translation>加载(&amp;L)…</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&amp;Run</source>
        <translation>运行(&amp;R)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+366"/>
        <source>P&amp;ause</source>
        <translation>暂停(&amp;A)</translation>
    </message>
    <message>
        <location line="-363"/>
        <source>&amp;Stop</source>
        <translation>停止(&amp;S)</translation>
    </message>
    <message>
        <source>Send nothing more and flush the device&apos;s queue (STOP)</source>
        <translation type="vanished">不再发送，并清空设备队列（STOP）</translation>
    </message>
    <message>
        <location line="-55"/>
        <source>Programs (*.gcode *.nc *.ngc *.tap *.dxf *.svg *.csv *.json);;G-code (*.gcode *.nc *.ngc *.tap);;DXF drawings (*.dxf);;SVG drawings (*.svg);;Points (*.csv *.json);;All files (*)</source>
        <translation>程序 (*.gcode *.nc *.ngc *.tap *.dxf *.svg *.csv *.json);;G-code (*.gcode *.nc *.ngc *.tap);;DXF 图纸 (*.dxf);;SVG 图纸 (*.svg);;点 (*.csv *.json);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Load a program: G-code, DXF or SVG, or points (CSV with x,y,z,speed in mm and mm/s, or JSON)</source>
        <translation>加载程序：G-code、DXF 或 SVG，或点（含 x,y,z,speed 列的 CSV，单位 mm 和 mm/s，或 JSON）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Run the program on the device (checked against the box first)</source>
        <translation>在设备上运行程序（先对照行程范围进行检查）</translation>
    </message>
    <message>
        <location line="+351"/>
        <source>Send nothing more until Resume (a device&apos;s queued moves go on)</source>
        <translation>在“继续”之前不再发送（设备已排队的移动照常执行）</translation>
    </message>
    <message>
        <location line="-344"/>
        <source>Send nothing more and stop the device (its queue flushed)</source>
        <translation>不再发送，并停止设备（清空其队列）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Chord tolerance: how far the straight moves an arc or curve is cut into may stray from it</source>
        <translation>弦公差：圆弧或曲线被切分成直线移动时，直线与其之间允许的最大偏差</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Instructions executed by the device</source>
        <translation>设备已执行的指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+137"/>
        <source>%v / %m executed</source>
        <translation>已执行 %v / %m</translation>
    </message>
    <message>
        <location line="-117"/>
        <source>The program&apos;s lines; the one under way is highlighted</source>
        <translation>程序的各行；正在执行的行会高亮显示</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The drawing&apos;s layers: the checked ones are run</source>
        <translation>图纸的图层：勾选的图层会被运行</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Program:</source>
        <translation>程序：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Chord tolerance:</source>
        <translation>弦公差：</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Load a program</source>
        <translation>加载程序</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Save the program</source>
        <translation>保存程序</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>JSON (*.json)</source>
        <translation>JSON (*.json)</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>reading %1…</source>
        <translation>正在读取 %1…</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 (%2 lines)</source>
        <translation>%1（%2 行）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (%2 entities)</source>
        <translation>%1（%2 个图元）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (%2 elements)</source>
        <translation>%1（%2 个元素）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2 points)</source>
        <translation>%1（%2 个点）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>no program</source>
        <translation>无程序</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>line %1</source>
        <translation>第 %1 行</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>entity %1</source>
        <translation>图元 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>element %1</source>
        <translation>元素 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point %1</source>
        <translation>点 %1</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>length %1 mm (travel moves %2 mm), %3 segments</source>
        <translation>长度 %1 mm（空移 %2 mm），%3 段</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>box X %1 to %2, Y %3 to %4, Z %5 to %6 mm</source>
        <translation>范围 X %1 至 %2，Y %3 至 %4，Z %5 至 %6 mm</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>about %1 (h:mm:ss) at %2 mm/s where the program sets no speed</source>
        <translation>约 %1（h:mm:ss），程序未设定速度处按 %2 mm/s 计</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>%1
Not for this program: %2</source>
        <translation>%1
不适用于此程序：%2</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>not connected to a device</source>
        <translation>未连接到设备</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>motion is off</source>
        <translation>运动控制不可用</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1
Refused: %2</source>
        <translation>%1
已拒绝：%2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1
Not now: %2</source>
        <translation>%1
暂不可用：%2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Send nothing more until Resume. This device has no feed hold: it goes on running the moves it already holds (the status line says how many, and when it stands still); Stop flushes them</source>
        <translation>在“继续”之前不再发送。此设备没有进给保持功能：它会继续执行已保有的移动（状态栏会显示数量以及何时静止）；“停止”可清除这些移动</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Send nothing more until Resume. The move under way finishes, then the stage stands still (this device has no feed hold)</source>
        <translation>在“继续”之前不再发送。进行中的移动会继续完成，随后平台静止（此设备没有进给保持功能）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>, paused</source>
        <translation>，已暂停</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, about %1 s left</source>
        <translation>，约剩 %1 s</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>sent %1, acknowledged %2, executed %3; %4 instructions/s%5; %6 retransmission(s)</source>
        <translation>已发送 %1，已确认 %2，已执行 %3；%4 条指令/s%5；重传 %6 次</translation>
    </message>
</context>
<context>
    <name>RawConsole</name>
    <message>
        <location filename="../../app/window/console/display.py" line="+16"/>
        <source>text</source>
        <translation>文本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hex</source>
        <translation>十六进制</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mixed</source>
        <translation>混合</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>relative</source>
        <translation>相对</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>absolute</source>
        <translation>绝对</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>delta</source>
        <translation>间隔</translation>
    </message>
    <message>
        <location filename="../../app/window/console/export.py" line="+18"/>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Text (*.txt)</source>
        <translation>文本 (*.txt)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>All files (*)</source>
        <translation>所有文件 (*)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export traffic</source>
        <translation>导出通信记录</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>exported %1 line to %2</source>
        <translation>已将 %1 行导出到 %2</translation>
    </message>
    <message>
        <location filename="../../app/window/console/display.py" line="+26"/>
        <source>Bytes as text (\r \n \xNN escapes), hex (47 45 54), or mixed (text, &lt;0A&gt; for the rest)</source>
        <translation>字节显示方式：文本（\r \n \xNN 转义）、十六进制（47 45 54）或混合（文本，其余字节显示为 &lt;0A&gt;）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Times: seconds since the session start, wall-clock time, or the gap since the line above</source>
        <translation>时间显示方式：自会话开始起的秒数、时钟时间，或与上一行的间隔</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Show the time column</source>
        <translation>显示时间列</translation>
    </message>
    <message>
        <location filename="../../app/window/console/filter_bar.py" line="+57"/>
        <source>TX</source>
        <translation>TX</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show what was sent to the device</source>
        <translation>显示发送到设备的内容</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>RX</source>
        <translation>RX</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show what the device sent</source>
        <translation>显示设备发送的内容</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Kinds</source>
        <translation>类型</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Which kinds of lines to show</source>
        <translation>要显示哪些类型的行</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Poll</source>
        <translation>轮询</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Show the idle position queries and their replies (hidden by default; counted below)</source>
        <translation>显示空闲时的位置查询及其应答（默认隐藏；数量见下方统计）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>filter (regex)</source>
        <translation>过滤（正则表达式）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Show only lines matching this regular expression (case-insensitive) in their direction, kind, hex, text or meaning, e.g. error|FA00</source>
        <translation>仅显示方向、类型、十六进制、文本或含义与此正则表达式匹配（不区分大小写）的行，例如 error|FA00</translation>
    </message>
    <message>
        <location filename="../../app/window/console/traffic_console.py" line="+124"/>
        <source>paused</source>
        <translation>已暂停</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>New lines do not scroll the view: scroll to the bottom to follow</source>
        <translation>新行不会滚动视图：滚动到底部即可继续跟随</translation>
    </message>
    <message>
        <location filename="../../app/window/console/filter_bar.py" line="+12"/>
        <source>search (regex)</source>
        <translation>搜索（正则表达式）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Highlight matching lines; Enter or F3: next, Shift+F3: previous</source>
        <translation>高亮匹配的行；Enter 或 F3：下一个，Shift+F3：上一个</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Previous match (Shift+F3)</source>
        <translation>上一个匹配项（Shift+F3）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Next match (F3)</source>
        <translation>下一个匹配项（F3）</translation>
    </message>
    <message>
        <location filename="../../app/window/console/status.py" line="+45"/>
        <source>Lines in the session, shown, hidden polls, errors, matches</source>
        <translation>会话中的行数、已显示、已隐藏的轮询、错误、匹配项</translation>
    </message>
    <message>
        <location filename="../../app/window/console/traffic_console.py" line="+18"/>
        <source>Export…</source>
        <translation>导出…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save the lines shown (filtered) as text or CSV</source>
        <translation>将显示的行（经过过滤）保存为文本或 CSV</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Clear</source>
        <translation>清除</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Forget the lines (the session log keeps them)</source>
        <translation>清除这些行（会话日志中仍保留）</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>TX (blue): sent to the device; RX (green): received; grey: notes and the device&apos;s own text; red: errors. Double-click a line to go to its request, reply or first copy.</source>
        <translation>TX（蓝色）：发送到设备；RX（绿色）：已接收；灰色：说明及设备自身输出的文本；红色：错误。双击某行可跳转到其请求、应答或首次出现处。</translation>
    </message>
    <message>
        <location line="+102"/>
        <source>the console keeps the newest %1 lines: older lines are dropped from it as new ones come; the session log keeps every line</source>
        <translation>控制台只保留最新的 %1 行：新行到来时，较旧的行会从控制台中移除；会话日志保留所有行</translation>
    </message>
    <message>
        <location line="+133"/>
        <source>line %1 is no longer in the console (its line limit dropped it); the session log has it</source>
        <translation>第 %1 行已不在控制台中（因行数上限被移除）；会话日志中仍有该行</translation>
    </message>
    <message>
        <source>%1 lines reached the console&apos;s limit and were cleared; the session log keeps them</source>
        <translation type="vanished">%1 行因达到控制台上限而被清除；会话日志中仍保留这些行</translation>
    </message>
    <message>
        <location filename="../../app/window/console/status.py" line="+16"/>
        <source>%1 line</source>
        <translation>%1 行</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 lines</source>
        <translation>%1 行</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 shown</source>
        <translation>显示 %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 older in the session log</source>
        <translation>会话日志中另有较早的 %1 行</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 poll hidden</source>
        <translation>隐藏轮询 %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 error</source>
        <translation>错误 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 errors</source>
        <translation>错误 %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 match</source>
        <translation>匹配 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 matches</source>
        <translation>匹配 %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 more hidden by the filters</source>
        <translation>另有 %1 个被过滤器隐藏</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The console keeps the newest %1 lines (Settings): older lines are dropped from it, the session log on disk keeps every line</source>
        <translation>控制台只保留最新的 %1 行（见“设置”）：较旧的行会从中移除，磁盘上的会话日志保留所有行</translation>
    </message>
    <message>
        <location filename="../../app/window/console/traffic_console.py" line="+114"/>
        <source>export failed: %1</source>
        <translation>导出失败：%1</translation>
    </message>
    <message>
        <location filename="../../app/window/console/export.py" line="+2"/>
        <source>exported %1 lines to %2</source>
        <translation>已将 %1 行导出到 %2</translation>
    </message>
    <message>
        <location filename="../../app/window/console/table.py" line="+60"/>
        <source>motion</source>
        <translation>运动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>query</source>
        <translation>查询</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>poll</source>
        <translation>轮询</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>setting</source>
        <translation>设置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error</source>
        <translation>错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>debug</source>
        <translation>调试</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>note</source>
        <translation>说明</translation>
    </message>
</context>
<context>
    <name>SendLine</name>
    <message>
        <location filename="../../widgets/send_line.py" line="+19"/>
        <source>text</source>
        <translation>文本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hex</source>
        <translation>十六进制</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>text: UTF-8 with \r \n \t \0 \\ \xNN escapes, plus the line ending;
hex: bytes like 48 45 4C 4C 4F, sent as they are</source>
        <translation>文本：UTF-8，支持 \r \n \t \0 \\ \xNN 转义，并附加行尾符；
十六进制：如 48 45 4C 4C 4F 这样的字节，按原样发送</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Appended to every line sent in text mode</source>
        <translation>文本模式下附加到发送的每一行末尾</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send</source>
        <translation>发送</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Send the line to the device (Enter)</source>
        <translation>将该行发送到设备（Enter）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Sen&amp;d:</source>
        <translation>发送(&amp;D)：</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>hex bytes, e.g. 48 45 4C 4C 4F (Up/Down: history)</source>
        <translation>十六进制字节，例如 48 45 4C 4C 4F（↑/↓：历史记录）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>text to send (Up/Down: history)</source>
        <translation>要发送的文本（↑/↓：历史记录）</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>nothing to send</source>
        <translation>没有要发送的内容</translation>
    </message>
</context>
<context>
    <name>SettingsDialog</name>
    <message>
        <location filename="../../widgets/settings_dialog.py" line="+78"/>
        <source>Settings</source>
        <translation>设置</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Connection</source>
        <translation>连接</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Console &amp;&amp; log</source>
        <translation>控制台 &amp;&amp; 日志</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Display</source>
        <translation>显示</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Keyboard jog</source>
        <translation>键盘点动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Appearance &amp;&amp; language</source>
        <translation>外观 &amp;&amp; 语言</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Use and save</source>
        <translation>应用并保存</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Use and save, and keep this open</source>
        <translation>应用并保存，且保持此窗口打开</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Put every field back to its default (saved only with OK or Apply)</source>
        <translation>将所有字段恢复为默认值（仅在点击“确定”或“应用”后保存）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Close without saving</source>
        <translation>关闭且不保存</translation>
    </message>
    <message>
        <location line="+103"/>
        <source>Position polling</source>
        <translation>位置轮询</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>How often the position is read while a move is being confirmed, in hertz (%1 to %2 Hz). Faster confirms the end of each jog step sooner; above 20 Hz nothing is seen sooner.</source>
        <translation>确认移动期间读取位置的频率，单位赫兹（%1 至 %2 Hz）。频率越高，越快确认每次点动结束；高于 20 Hz 也不会更早看到结果。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Poll while moving:</source>
        <translation>移动时轮询：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Seconds between position reads while nothing moves (%1 to %2 s). This is also how a device that restarted or stopped answering is noticed.</source>
        <translation>静止时两次读取位置之间的秒数（%1 至 %2 s）。设备重启或停止应答也是借此发现的。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Poll when idle:</source>
        <translation>空闲时轮询：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Console</source>
        <translation>控制台</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> lines</source>
        <translation> 行</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep every line</source>
        <translation>保留所有行</translation>
    </message>
    <message>
        <source>The most lines the console keeps: 0 keeps every line (a spool file on disk and about 33 bytes a line in memory), else %1 to %2 lines. The session log keeps every byte either way.</source>
        <translation type="vanished">控制台最多保留的行数：0 表示保留所有行（磁盘上使用缓存文件，内存中每行约 33 字节），否则为 %1 至 %2 行。无论如何，会话日志都会保存每个字节。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The most lines the console keeps: 0 keeps every line (a spool file on disk and about 33 bytes a line in memory), else %1 to %2 lines, the oldest dropped as new ones come. The session log keeps every byte either way.</source>
        <translation>控制台最多保留的行数：0 表示保留所有行（磁盘上使用缓存文件，内存中每行约 33 字节），否则为 %1 至 %2 行，新行到来时移除最旧的行。无论如何，会话日志都会保存每个字节。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Console lines kept:</source>
        <translation>控制台保留行数：</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Session log</source>
        <translation>会话日志</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write every byte of every session to a file</source>
        <translation>将每次会话的每个字节写入文件</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>One file a session in the log folder; the oldest go beyond 200 MiB</source>
        <translation>日志文件夹中每次会话一个文件；总量超过 200 MiB 时删除最旧的文件</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the app-data folder</source>
        <translation>应用数据文件夹</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Default: %1</source>
        <translation>默认：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>An absolute path to a folder you can write to; empty: the default folder</source>
        <translation>可写入的文件夹的绝对路径；留空：使用默认文件夹</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Browse…</source>
        <translation>浏览…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose the session log folder</source>
        <translation>选择会话日志文件夹</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Session log folder:</source>
        <translation>会话日志文件夹：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Positions</source>
        <translation>位置</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Millimetres (mm)</source>
        <translation>毫米（mm）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Inches (in)</source>
        <translation>英寸（in）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The unit positions are shown in; the device is always sent millimetres</source>
        <translation>位置的显示单位；发送给设备的始终是毫米</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Units shown:</source>
        <translation>显示单位：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> decimals</source>
        <translation> 位小数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>As the device resolves</source>
        <translation>按设备分辨率</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Decimals of the positions shown (%1 to %2), or as many as the device resolves (0.01 mm: 2)</source>
        <translation>位置显示的小数位数（%1 至 %2），或按设备分辨率确定（0.01 mm：2 位）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Decimals shown:</source>
        <translation>显示小数位数：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Travel limits</source>
        <translation>行程限位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clamp a move to the limits instead of refusing it</source>
        <translation>将移动限制在限位内，而不是拒绝执行</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>What a device starts with until its own limits are saved</source>
        <translation>设备保存自身限位之前使用的初始设置</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Each device&apos;s box is set in Motion → Travel limits…</source>
        <translation>每台设备的范围在“运动 → 行程限位…”中设置</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Jog keys</source>
        <translation>点动按键</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>X-:</source>
        <translation>X-：</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog X down by one step</source>
        <translation>X 轴负向点动一步</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X+:</source>
        <translation>X+：</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog X up by one step</source>
        <translation>X 轴正向点动一步</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y-:</source>
        <translation>Y-：</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog Y down by one step</source>
        <translation>Y 轴负向点动一步</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y+:</source>
        <translation>Y+：</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog Y up by one step</source>
        <translation>Y 轴正向点动一步</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z-:</source>
        <translation>Z-：</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog Z down by one step</source>
        <translation>Z 轴负向点动一步</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z+:</source>
        <translation>Z+：</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog Z up by one step</source>
        <translation>Z 轴正向点动一步</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Smaller step:</source>
        <translation>较小步长：</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The next smaller step</source>
        <translation>切换到下一个较小步长</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Larger step:</source>
        <translation>较大步长：</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The next larger step</source>
        <translation>切换到下一个较大步长</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Click, then press one key (no Shift, Ctrl, Alt or Meta)</source>
        <translation>点击后按一个键（不含 Shift、Ctrl、Alt 或 Meta）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Shift with a jog key makes the step ten times bigger. Esc (Stop), Tab, Enter, Space and F3 are the window&apos;s own.</source>
        <translation>按住 Shift 再按点动键，步长放大十倍。Esc（停止）、Tab、Enter、Space 和 F3 为窗口自用按键。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Appearance and language</source>
        <translation>外观和语言</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+10"/>
        <source>As the system</source>
        <translation>跟随系统</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>Light</source>
        <translation>浅色</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dark</source>
        <translation>深色</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Light or dark colours, or those of the desktop</source>
        <translation>浅色或深色配色，或跟随桌面配色</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Theme:</source>
        <translation>主题：</translation>
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
        <translation>界面语言；--lang 和 $MOTIONPANEL_LANG 优先</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Language:</source>
        <translation>语言：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A new language shows when the panel next starts.</source>
        <translation>新语言将在面板下次启动时生效。</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>%1: %2 is not a number from %3 to %4 %5</source>
        <translation>%1：%2 不是有效数字，应为 %3 至 %4 %5</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Memory grows with the session: about 33 MB a million lines.</source>
        <translation>内存占用随会话增长：每百万行约 33 MB。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>About %1 MB of memory at most.</source>
        <translation>最多占用约 %1 MB 内存。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Session log folder</source>
        <translation>会话日志文件夹</translation>
    </message>
</context>
<context>
    <name>ShortcutsDialog</name>
    <message>
        <location filename="../../widgets/shortcuts_dialog.py" line="+75"/>
        <source>Keyboard Shortcuts</source>
        <translation>键盘快捷键</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Search shortcuts…</source>
        <translation>搜索快捷键…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Search shortcuts</source>
        <translation>搜索快捷键</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Keys</source>
        <translation>按键</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Action</source>
        <translation>操作</translation>
    </message>
    <message>
        <location line="+77"/>
        <source>No shortcut matches “%1”.</source>
        <translation>没有与“%1”匹配的快捷键。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No keyboard shortcuts.</source>
        <translation>没有键盘快捷键。</translation>
    </message>
</context>
<context>
    <name>SpeedControl</name>
    <message>
        <location filename="../../widgets/speed_control.py" line="+53"/>
        <source>Speed:</source>
        <translation>速度：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed of the next moves</source>
        <translation>后续移动的速度</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Apply</source>
        <translation>应用</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+45"/>
        <source>Send the speed in the field to the device</source>
        <translation>将输入框中的速度发送到设备</translation>
    </message>
    <message>
        <location line="-40"/>
        <source>The speed the device reports (it may round)</source>
        <translation>设备报告的速度（可能经过取整）</translation>
    </message>
    <message>
        <location line="+122"/>
        <source>Speed, %1 to %2 in/s; press Enter or Apply to send</source>
        <translation>速度，%1 至 %2 in/s；按 Enter 或“应用”发送</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag and release to send (%1 to %2 in/s)</source>
        <translation>拖动后松开即发送（%1 至 %2 in/s）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Speed, %1 to %2 mm/s; press Enter or Apply to send</source>
        <translation>速度，%1 至 %2 mm/s；按 Enter 或“应用”发送</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag and release to send (%1 to %2 mm/s)</source>
        <translation>拖动后松开即发送（%1 至 %2 mm/s）</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>device: %1 in/s</source>
        <translation>设备：%1 in/s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>device: %1 mm/s</source>
        <translation>设备：%1 mm/s</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+3"/>
        <source>%1; nothing sent</source>
        <translation>%1；未发送任何内容</translation>
    </message>
</context>
<context>
    <name>StatusLine</name>
    <message>
        <location filename="../../widgets/status_line.py" line="+19"/>
        <source>Disconnected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No device is connected</source>
        <translation>未连接任何设备</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+47"/>
        <source>Connecting…</source>
        <translation>正在连接…</translation>
    </message>
    <message>
        <location line="-45"/>
        <source>Opening the port and asking the device who it is</source>
        <translation>正在打开端口并查询设备身份</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Idle</source>
        <translation>空闲</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Connected and not moving</source>
        <translation>已连接，未在移动</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Moving</source>
        <translation>移动中</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A move is under way</source>
        <translation>正在移动</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Busy</source>
        <translation>忙碌</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A command is under way</source>
        <translation>正在执行命令</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Paused</source>
        <translation>已暂停</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A program is paused: nothing more of it is sent until Resume</source>
        <translation>程序已暂停：在“继续”之前不再发送其任何内容</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Error</source>
        <translation>错误</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The last command failed, or the connection did</source>
        <translation>上一条命令失败，或连接出错</translation>
    </message>
</context>
<context>
    <name>ThemeMenu</name>
    <message>
        <location filename="../../app/window/theme.py" line="+373"/>
        <source>&amp;Theme</source>
        <translation>主题(&amp;T)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Follow the &amp;system</source>
        <translation>跟随系统(&amp;S)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Light</source>
        <translation>浅色(&amp;L)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Dark</source>
        <translation>深色(&amp;D)</translation>
    </message>
</context>
<context>
    <name>TrafficFormat</name>
    <message>
        <location filename="../../widgets/traffic_format.py" line="+38"/>
        <source>\x needs two hex digits at column %1: %2</source>
        <translation>第 %1 列的 \x 需要两位十六进制数字：%2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>a lone backslash ends the line: write \\ for a backslash</source>
        <translation>行尾有单独的反斜杠：反斜杠本身请写作 \\</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>unknown escape \%1 at column %2 (use \r \n \t \0 \\ \xNN)</source>
        <translation>第 %2 列有未知的转义 \%1（可用 \r \n \t \0 \\ \xNN）</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>not hex: %1</source>
        <translation>不是十六进制：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>odd number of hex digits in %1: write 0%2 or pairs</source>
        <translation>%1 中的十六进制数字个数为奇数：请写作 0%2 或两位一组</translation>
    </message>
</context>
<context>
    <name>TrafficModel</name>
    <message>
        <location filename="../../app/window/console/table.py" line="-21"/>
        <source>Line</source>
        <translation>行号</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dir</source>
        <translation>方向</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bytes</source>
        <translation>字节</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Meaning</source>
        <translation>含义</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reply</source>
        <translation>应答</translation>
    </message>
    <message>
        <location line="+316"/>
        <source>line %1: %2</source>
        <translation>第 %1 行：%2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>hex: %1</source>
        <translation>十六进制：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>text: %1</source>
        <translation>文本：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 (double-click to go there)</source>
        <translation>%1（双击跳转到该处）</translation>
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
        <translation>跟随</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Keep the latest %1 s in view; zooming or panning stops it</source>
        <translation>始终显示最近 %1 s；缩放或平移会停止跟随</translation>
    </message>
    <message>
        <location filename="../../widgets/timeline/plots.py" line="+32"/>
        <source>Bytes per second each way, in one-second bins: TX (blue) sent to the device, RX (green) received. Click a bin to show its first line in the console.</source>
        <translation>每个方向每秒的字节数，按一秒分段统计：TX（蓝色）为发送到设备的数据，RX（绿色）为接收的数据。点击某一分段可在控制台中显示其第一行。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>rate</source>
        <translation>速率</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Bytes per second</source>
        <translation>每秒字节数</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Command latency</source>
        <translation>命令延迟</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Time from a request to its reply, in ms: one point per answered request (drawn as dots when few are in view). Click a point to show its line in the console.</source>
        <translation>从请求到应答的时间，单位 ms：每个已应答的请求对应一个点（视图中点较少时绘制为圆点）。点击某个点可在控制台中显示其对应行。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>latency</source>
        <translation>延迟</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>time since the session started</source>
        <translation>自会话开始起的时间</translation>
    </message>
</context>
<context>
    <name>TravelLimitsDialog</name>
    <message>
        <location filename="../../widgets/travel_limits_dialog.py" line="+19"/>
        <source>Travel limits</source>
        <translation>行程限位</translation>
    </message>
    <message>
        <source>Where the stage may go on %1. A jog, go-to or command-line move that would leave the box is refused before anything is sent, or clamped to its edge.</source>
        <translation type="vanished">平台在 %1 上允许到达的范围。若点动、定位或命令行移动会超出此范围，将在发送任何内容之前被拒绝，或被限制到边界。</translation>
    </message>
    <message>
        <source>Limit moves to this box</source>
        <translation type="vanished">将移动限制在此范围内</translation>
    </message>
    <message>
        <source>min</source>
        <translation type="vanished">最小</translation>
    </message>
    <message>
        <source>max</source>
        <translation type="vanished">最大</translation>
    </message>
    <message>
        <source>%1:</source>
        <comment>an axis field&apos;s label</comment>
        <translation type="vanished">%1：</translation>
    </message>
    <message>
        <source>%1 min</source>
        <comment>an axis&apos; lower travel limit</comment>
        <translation type="vanished">%1 最小值</translation>
    </message>
    <message>
        <source>%1 max</source>
        <comment>an axis&apos; upper travel limit</comment>
        <translation type="vanished">%1 最大值</translation>
    </message>
    <message>
        <source>Refuse a move that would leave the box</source>
        <translation type="vanished">拒绝会超出范围的移动</translation>
    </message>
    <message>
        <source>Clamp it: go as far as the edge, and say so</source>
        <translation type="vanished">限制：移动到边界为止，并给出提示</translation>
    </message>
    <message>
        <source>%1: the minimum must be below the maximum</source>
        <translation type="vanished">%1：最小值必须小于最大值</translation>
    </message>
</context>
<context>
    <name>TravelLimitsForm</name>
    <message>
        <location filename="../../widgets/travel_limits_form.py" line="+45"/>
        <source>Limit moves to this box</source>
        <translation>将移动限制在此范围内</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>min</source>
        <translation>最小</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max</source>
        <translation>最大</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1:</source>
        <comment>an axis field&apos;s label</comment>
        <translation>%1：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 min</source>
        <comment>an axis&apos; lower travel limit</comment>
        <translation>%1 最小值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 max</source>
        <comment>an axis&apos; upper travel limit</comment>
        <translation>%1 最大值</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Refuse a move that would leave the box</source>
        <translation>拒绝会超出范围的移动</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Clamp it: go as far as the edge, and say so</source>
        <translation>限制：移动到边界为止，并给出提示</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Where the stage may go on %1. A jog, go-to or command-line move that would leave the box is refused before anything is sent, or clamped to its edge.</source>
        <translation>平台在 %1 上允许到达的范围。若点动、定位或命令行移动会超出此范围，将在发送任何内容之前被拒绝，或被限制到边界。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Connect a device to set where its stage may go.</source>
        <translation>请连接设备，以设置其平台允许到达的范围。</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>%1: the minimum must be below the maximum</source>
        <translation>%1：最小值必须小于最大值</translation>
    </message>
</context>
<context>
    <name>TravelLimitsPanel</name>
    <message>
        <location line="+25"/>
        <source>Apply</source>
        <translation>应用</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Use these limits for this device from now on (kept for it)</source>
        <translation>从现在起对此设备使用这些限位（为其保存）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Revert</source>
        <translation>还原</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Show the limits in use again</source>
        <translation>重新显示正在使用的限位</translation>
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
        <translation>%1：编辑已取消，值未更改</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 is an output. %2</source>
        <translation>%1 是输出参数。%2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1 = %2, not yet written to the device</source>
        <translation>%1 = %2，尚未写入设备</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1. Warning: %2</source>
        <translation>%1。警告：%2</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1: %2 (Enter keeps it, Escape cancels)</source>
        <translation>%1：%2（按 Enter 保留，按 Escape 取消）</translation>
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
        <translation>XY 与时间</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The path in 3D</source>
        <translation>3D 路径</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The path seen from above and X, Y, Z against time</source>
        <translation>俯视路径，以及 X、Y、Z 随时间的变化</translation>
    </message>
</context>
<context>
    <name>WindowTools</name>
    <message>
        <location filename="../../app/window/window_tools.py" line="+48"/>
        <source>Macros</source>
        <translation>宏</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>&amp;Settings…</source>
        <translation>设置(&amp;S)…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Poll rates, console, log folder, units, jog keys, theme</source>
        <translation>轮询频率、控制台、日志文件夹、单位、点动按键、主题</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Keyboard shortcuts</source>
        <translation>键盘快捷键(&amp;K)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;About Motion Panel</source>
        <translation>关于 Motion Panel(&amp;A)</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>Jog X - / +</source>
        <translation>X 轴点动 - / +</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jog Y - / +</source>
        <translation>Y 轴点动 - / +</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jog Z - / +</source>
        <translation>Z 轴点动 - / +</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shift + a jog key</source>
        <translation>Shift + 点动键</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Jog ten times the step</source>
        <translation>以十倍步长点动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hold a jog key</source>
        <translation>按住点动键</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Keep jogging until it is released</source>
        <translation>持续点动，直到松开按键</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Keys: %1/%2 X, %3/%4 Y, %5/%6 Z, Shift ×10</source>
        <translation>按键：%1/%2 X，%3/%4 Y，%5/%6 Z，Shift ×10</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>, %1/%2 step</source>
        <translation>，%1/%2 步长</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>settings saved; the language from the next start</source>
        <translation>设置已保存；语言将在下次启动时生效</translation>
    </message>
    <message>
        <source>the session log from the next start</source>
        <translation type="vanished">会话日志设置将在下次启动时生效</translation>
    </message>
    <message>
        <source>the language from the next start</source>
        <translation type="vanished">语言将在下次启动时生效</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>settings saved</source>
        <translation>设置已保存</translation>
    </message>
    <message>
        <source>settings saved; %1</source>
        <translation type="vanished">设置已保存；%1</translation>
    </message>
</context>
<context>
    <name>WorkFrame</name>
    <message>
        <location filename="../../app/window/docks/work_frame.py" line="+59"/>
        <source>work coordinates: %1</source>
        <translation>工件坐标：%1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>work zero not set: the position is unknown</source>
        <translation>未设置工件零点：位置未知</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>work zero set at %1 %2 (machine)</source>
        <translation>工件零点已设于 %1 %2（机床坐标）</translation>
    </message>
    <message>
        <source>work zero set at %1 mm (machine)</source>
        <translation type="vanished">工件零点已设于 %1 mm（机床坐标）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>work zero cleared: work coordinates are machine coordinates</source>
        <translation>工件零点已清除：工件坐标即机床坐标</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>work zero kept in place: %1</source>
        <translation>工件零点保持不变：%1</translation>
    </message>
</context>
<context>
    <name>messages</name>
    <message>
        <location filename="message_templates.py" line="+15"/>
        <source>to ({x:g}, {y:g}, {z:g}) mm</source>
        <translation>前往 ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>to its target</source>
        <translation>前往其目标</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: COXIRIS has no stop command; the device finishes the move under way {target} (a blocking sketch answers nothing until then) and then carries out what it had already received; motionctl sent nothing more</source>
        <translation>已中断：COXIRIS 没有停止命令；设备会继续完成{target}的当前移动（阻塞式 sketch 在此之前不作任何应答），然后执行它已收到的命令；motionctl 未再发送任何内容</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: Visiomex has no stop command; the device carries out the move packet it was sent {target} (FP0001, its steps, then FA0001); motionctl sent nothing more</source>
        <translation>已中断：Visiomex 没有停止命令；设备会执行已发给它的、{target}的移动数据包（FP0001、各步，然后 FA0001）；motionctl 未再发送任何内容</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: pi-frame has no stop command and sends no replies; the device carries out the frame it was sent {target}; motionctl sent nothing more</source>
        <translation>已中断：pi-frame 没有停止命令，也不发送应答；设备会执行已发给它的、{target}的帧；motionctl 未再发送任何内容</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: Firmata has no stop command; the board finishes the step message under way (at most 16383 steps) and stops there; the move&apos;s later messages, if it had more, were not sent</source>
        <translation>已中断：Firmata 没有停止命令；控制板会完成正在执行的步进消息（最多 16383 步）并停在该处；该移动后续的消息（如果还有）未发送</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: {protocol} has no stop command; the device finishes what it was sent; motionctl sent nothing more</source>
        <translation>已中断：{protocol} 没有停止命令；设备会完成已发给它的内容；motionctl 未再发送任何内容</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted before the device was talked to: nothing was sent</source>
        <translation>在与设备通信之前已中断：未发送任何内容</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: {command} does not move the stage</source>
        <translation>已中断：{command} 不会移动平台</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted before the move was sent: the stage does not move</source>
        <translation>在发送移动之前已中断：平台不会移动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted again while stopping: the {protocol} stop may not have arrived; the device may still be moving</source>
        <translation>停止过程中再次中断：{protocol} 停止命令可能未送达；设备可能仍在移动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: the {protocol} stop was sent but not acknowledged ({error}); the device may still be moving</source>
        <translation>已中断：{protocol} 停止命令已发送但未得到确认（{error}）；设备可能仍在移动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted again</source>
        <translation>再次中断</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: stopped (the {protocol} stop was acknowledged; its queue is flushed); where the stage stopped could not be read: {error}</source>
        <translation>已中断：已停止（{protocol} 停止命令已确认；其队列已清空）；无法读取平台停止的位置：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: stopped at ({x:g}, {y:g}, {z:g}) mm (the {protocol} stop was acknowledged; its queue is flushed)</source>
        <translation>已中断：已停止于 ({x:g}, {y:g}, {z:g}) mm（{protocol} 停止命令已确认；其队列已清空）</translation>
    </message>
    <message>
        <location line="-17"/>
        <source>usage: {usage} (got {count} arguments)</source>
        <translation>用法：{usage}（收到 {count} 个参数）</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>--force is for raw only</source>
        <translation>--force 仅适用于 raw</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command} needs --port (the device to talk to)</source>
        <translation>{command} 需要 --port（要通信的设备）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command} needs --protocol ({choices})</source>
        <translation>{command} 需要 --protocol（{choices}）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>usage: {usage}</source>
        <translation>用法：{usage}</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>--kind {kind} refused: --kind is for jog only (move is in mm)</source>
        <translation>--kind {kind} 被拒绝：--kind 仅适用于 jog（move 的单位为 mm）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>usage: {command} {axes} ({protocol} has {count} axes)</source>
        <translation>用法：{command} {axes}（{protocol} 有 {count} 个轴）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>--kind {kind} refused: {protocol} moves are {kinds}</source>
        <translation>--kind {kind} 被拒绝：{protocol} 的移动类型为 {kinds}</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>speed {speed:g} mm/s refused: the device allows {low:g} to {high:g} mm/s</source>
        <translation>速度 {speed:g} mm/s 被拒绝：设备允许 {low:g} 至 {high:g} mm/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed {speed:g} mm/s refused ({error})</source>
        <translation>速度 {speed:g} mm/s 被拒绝（{error}）</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>raw move to ({x:g}, {y:g}, {z:g}) mm</source>
        <translation>原始命令移动到 ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <source>{file} names no protocol (no connection note: a motionctl --log file or a spy:// capture has none): give --protocol</source>
        <translation type="vanished">{file} 未指明协议（没有连接说明：motionctl --log 文件或 spy:// 捕获文件都不含连接说明）：请指定 --protocol</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>{file}: its connection note: {error}</source>
        <translation>{file}：其连接说明：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>its connection notes name {named}</source>
        <translation>其连接说明指明的是 {named}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>try another --protocol</source>
        <translation>请尝试其他 --protocol</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nothing in {file} decodes as {protocol} ({count} records of traffic, none a {protocol} frame); {hint}</source>
        <translation>{file} 中没有任何内容能按 {protocol} 解码（共 {count} 条通信记录，没有一条是 {protocol} 帧）；{hint}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SVG scale {value:g} refused: it must be above 0</source>
        <translation>SVG 缩放比例 {value:g} 被拒绝：必须大于 0</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>macro {name} ({count} step)</source>
        <translation>宏 {name}（{count} 步）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name} ({count} steps)</source>
        <translation>宏 {name}（{count} 步）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a macro needs a name</source>
        <translation>宏需要名称</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro name {name!r}… is over {limit} characters</source>
        <translation>宏名称 {name!r}… 超过 {limit} 个字符</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro name {name!r} holds a control character</source>
        <translation>宏名称 {name!r} 含有控制字符</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name} is for {protocol}, not {device}</source>
        <translation>宏 {name} 适用于 {protocol}，而非 {device}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name} has no steps</source>
        <translation>宏 {name} 没有步骤</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name} has {count} steps; at most {limit}</source>
        <translation>宏 {name} 有 {count} 个步骤；最多 {limit} 个</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name}, step {number} ({step!r}): {error}</source>
        <translation>宏 {name}，第 {number} 步（{step!r}）：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the step is over {limit} characters</source>
        <translation>步骤超过 {limit} 个字符</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a step is one line (use one step per line)</source>
        <translation>一个步骤只能占一行（每行一个步骤）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the step is empty</source>
        <translation>步骤为空</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown command {command!r}; a step is one of: {commands}</source>
        <translation>未知命令 {command!r}；步骤须为以下之一：{commands}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command} is a {owner} command</source>
        <translation>{command} 是 {owner} 的命令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>usage: wait SECONDS</source>
        <translation>用法：wait SECONDS（秒数）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wait {seconds:g} s refused: from 0 to {limit:g} s</source>
        <translation>等待 {seconds:g} s 被拒绝：应为 0 至 {limit:g} s</translation>
    </message>
    <message>
        <source>{name} stopped before step {number} ({step})</source>
        <translation type="vanished">{name} 在第 {number} 步（{step}）之前已停止</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name} stopped before step {number} ({step})</source>
        <translation>宏 {name} 在第 {number} 步（{step}）之前已停止</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro {name} stopped during step {number}</source>
        <translation>宏 {name} 在第 {number} 步期间已停止</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: not a Motion Panel macro file (no &quot;format&quot;: &quot;{format}&quot;)</source>
        <translation>{where}：不是 Motion Panel 宏文件（缺少 &quot;format&quot;: &quot;{format}&quot;）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: macro file version {version!r}; this reads {reads}</source>
        <translation>{where}：宏文件版本为 {version!r}；本程序只能读取版本 {reads}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: &quot;macros&quot; is not a list</source>
        <translation>{where}：&quot;macros&quot; 不是列表</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {count} macros; at most {limit}</source>
        <translation>{where}：{count} 个宏；最多 {limit} 个</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: macro {number}</source>
        <translation>{where}：第 {number} 个宏</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: two {protocol} macros are named {name!r}</source>
        <translation>{where}：有两个 {protocol} 宏都名为 {name!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where} is not an object with name, protocol and steps</source>
        <translation>{where} 不是含 name、protocol 和 steps 的对象</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where} has no name</source>
        <translation>{where} 没有名称</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where} ({name!r}): unknown protocol {protocol!r}</source>
        <translation>{where}（{name!r}）：未知协议 {protocol!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where} ({name!r}): &quot;steps&quot; is not a list of strings</source>
        <translation>{where}（{name!r}）：&quot;steps&quot; 不是字符串列表</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where} ({name!r}): over {limit} steps or a step too long</source>
        <translation>{where}（{name!r}）：步骤超过 {limit} 个，或有步骤过长</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>macro file</source>
        <translation>宏文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{path}: not JSON ({error})</source>
        <translation>{path}：不是 JSON（{error}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} is not a JSON number</source>
        <translation>{name} 不是 JSON 数字</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>saved macros</source>
        <translation>已保存的宏</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>it cannot be read</source>
        <translation>文件不可读</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>it is not an INI file Qt can read</source>
        <translation>不是 Qt 可读取的 INI 文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>settings file</source>
        <translation>设置文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot read the settings file {file}: {why}</source>
        <translation>无法读取设置文件 {file}：{why}</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>{url} ({protocol}, {baud} baud)</source>
        <translation>{url}（{protocol}，{baud} 波特）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{error}; waiting for {url}</source>
        <translation>{error}；正在等待 {url}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the saved setup was refused: {error}</source>
        <translation>设备拒绝了已保存的设置：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{identity} on {url}</source>
        <translation>{url} 上的 {identity}</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>{line} not changed: not connected</source>
        <translation>{line} 未更改：未连接</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no break sent: not connected</source>
        <translation>未发送中断信号：未连接</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>the position went from ({position}) to (0, 0, 0) mm while nothing was sent: the device restarted</source>
        <translation>未发送任何内容时，位置从 ({position}) 变为 (0, 0, 0) mm：设备已重启</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>{error}; not sent: {jobs}; talking to it again</source>
        <translation>{error}；未发送：{jobs}；正在重新与设备通信</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>{error}; talking to it again</source>
        <translation>{error}；正在重新与设备通信</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not sent: the device is being reconnected</source>
        <translation>未发送：正在重新连接设备</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>stopped before it was sent</source>
        <translation>发送前已停止</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the connection was lost</source>
        <translation>连接已断开</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>abandoned: disconnected while it was under way</source>
        <translation>已放弃：执行期间连接已断开</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>relative move by ({dx:g}, {dy:g}, {dz:g}) {unit}</source>
        <translation>相对移动 ({dx:g}, {dy:g}, {dz:g}) {unit}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown job {job!r}</source>
        <translation>未知任务 {job!r}</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>{hint} ({error})</source>
        <translation>{hint}（{error}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{error}; not sent: {jobs}</source>
        <translation>{error}；未发送：{jobs}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{error}; connecting again when {url} is back</source>
        <translation>{error}；{url} 恢复后将重新连接</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{url} is back: connecting again</source>
        <translation>{url} 已恢复：正在重新连接</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device says: {text}</source>
        <translation>设备消息：{text}</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the bridge to {device} is closed</source>
        <translation>到 {device} 的桥接已关闭</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot create a pseudo-terminal for {device}: {error}</source>
        <translation>无法为 {device} 创建伪终端：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bridge is not open</source>
        <translation>桥接未打开</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device on {device} failed: {error}</source>
        <translation>{device} 上的设备出错：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device on {device} went away: {error}</source>
        <translation>{device} 上的设备已断开：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device on {device} went away (its port was closed)</source>
        <translation>{device} 上的设备已断开（其端口已关闭）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the pseudo-terminal {path} failed: {error}</source>
        <translation>伪终端 {path} 出错：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>writing to the device on {device} failed: {error}</source>
        <translation>写入 {device} 上的设备失败：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>writing to the pseudo-terminal {path} failed: {error}</source>
        <translation>写入伪终端 {path} 失败：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>abandoned: the connection is closing</source>
        <translation>已放弃：连接正在关闭</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{error}; still full after {seconds:.0f} s</source>
        <translation>{error}；{seconds:.0f} s 后队列仍满</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command} failed after {tries} tries; the last: {error}</source>
        <translation>{command} 尝试 {tries} 次后失败；最后一次：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device restarted during {command} ({event}): its position and settings are lost</source>
        <translation>设备在执行 {command} 期间重启（{event}）：其位置和设置已丢失</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device restarted ({event}): its position and settings are lost</source>
        <translation>设备已重启（{event}）：其位置和设置已丢失</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device did not finish its reply to {command} within {seconds:.3g} s</source>
        <translation>设备未在 {seconds:.3g} s 内完成对 {command} 的应答</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device did not answer to {command} within {seconds:.3g} s</source>
        <translation>设备未在 {seconds:.3g} s 内应答 {command}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{message}; it sent {count} unexpected frame(s), the last: {frame}</source>
        <translation>{message}；设备发送了 {count} 个意外的帧，最后一个：{frame}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{message} (it may still be moving: {protocol} answers nothing until a blocking move has ended; try again once it has stopped)</source>
        <translation>{message}（设备可能仍在移动：{protocol} 在阻塞式移动结束前不作任何应答；请在其停止后重试）</translation>
    </message>
    <message>
        <location line="+87"/>
        <source>no modem control lines</source>
        <translation>没有调制解调器控制信号线</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{dtr}, {rts}, {cts}, {dsr}, {cd}, {ri}</source>
        <translation>{dtr}，{rts}，{cts}，{dsr}，{cd}，{ri}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{line} ?</source>
        <translation>{line} ?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{line} on</source>
        <translation>{line} 开</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{line} off</source>
        <translation>{line} 关</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>unreadable: {error}</source>
        <translation>无法解读：{error}</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>error {code}: {message}</source>
        <translation>错误 {code}：{message}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error: {message}</source>
        <translation>错误：{message}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position unknown (({x:g}, {y:g}, {z:g}) mm counted from where the session began; Home or Set Home to know it)</source>
        <translation>位置未知（从会话开始处计数为 ({x:g}, {y:g}, {z:g}) mm；请回原点或设为原点以确定位置）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position ({x:g}, {y:g}, {z:g}) mm</source>
        <translation>位置 ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position ({x:g}, {y:g}, {z:g}) mm (commanded, confirmed)</source>
        <translation>位置 ({x:g}, {y:g}, {z:g}) mm（指令值，已确认）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position ({x:g}, {y:g}, {z:g}) mm (commanded)</source>
        <translation>位置 ({x:g}, {y:g}, {z:g}) mm（指令值）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>feedback {code} ({meaning})</source>
        <translation>反馈 {code}（{meaning}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>feedback {code} {bytes}</source>
        <translation>反馈 {code} {bytes}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>feedback {code}</source>
        <translation>反馈 {code}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the line {text!r}</source>
        <translation>文本行 {text!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an unreadable frame ({reason}): {bytes}</source>
        <translation>无法解读的帧（{reason}）：{bytes}</translation>
    </message>
    <message>
        <location line="-95"/>
        <source>a directory</source>
        <translation>目录</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a named pipe (FIFO)</source>
        <translation>命名管道（FIFO）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a character device</source>
        <translation>字符设备</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a block device</source>
        <translation>块设备</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a socket</source>
        <translation>套接字</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot read the {what} {file}: {why}</source>
        <translation>无法读取{what} {file}：{why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{kind}, not a regular file</source>
        <translation>是{kind}，而非普通文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a special file</source>
        <translation>特殊文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: larger than {limit} ({size:,} bytes), too large for a {what}</source>
        <translation>{file}：超过 {limit}（{size:,} 字节），作为{what}过大</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: larger than {limit}, too large for a {what}</source>
        <translation>{file}：超过 {limit}，作为{what}过大</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: not UTF-8 text (line {line}), not a {what}</source>
        <translation>{file}：不是 UTF-8 文本（第 {line} 行），不是{what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: a NUL byte (line {line}), not a {what}</source>
        <translation>{file}：含有 NUL 字节（第 {line} 行），不是{what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file} line {line}: longer than {limit:,} characters, not a {what} line</source>
        <translation>{file} 第 {line} 行：超过 {limit:,} 个字符，不是{what}行</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a frame body is {expected} bytes, not {length}</source>
        <translation>帧体应为 {expected} 字节，而不是 {length} 字节</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>flag byte {byte:#04x}, expected 0xf0</source>
        <translation>标志字节为 {byte:#04x}，应为 0xf0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>checksum {got:#04x}, expected {expected:#04x}</source>
        <translation>校验和为 {got:#04x}，应为 {expected:#04x}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0x90 followed by {byte:#04x} inside the data</source>
        <translation>数据中 0x90 之后跟随 {byte:#04x}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no tail within {most} bytes</source>
        <translation>{most} 字节内没有帧尾</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a SysEx message needs at least a command byte</source>
        <translation>SysEx 消息至少需要一个命令字节</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SysEx data must be 7-bit; got {byte:#04x}</source>
        <translation>SysEx 数据必须为 7 位；收到 {byte:#04x}</translation>
    </message>
    <message>
        <location line="+356"/>
        <source>{source} names no protocol: decoded as {protocol}, which its traffic reads as ({frames} frames recognised)</source>
        <translation>{source} 未指明协议：按 {protocol} 解码，其通信内容符合该协议（识别出 {frames} 帧）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {number}: not a traffic log line: {line!r}</source>
        <translation>{source} 第 {number} 行：不是通信日志行：{line!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no traffic in it (not a Motion Panel log)</source>
        <translation>{source}：其中没有通信记录（不是 Motion Panel 日志）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>traffic log</source>
        <translation>通信日志</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: not a Motion Panel log nor a pyserial spy:// capture: line {number} is not a traffic log line: {line!r}; for spy://, {hint}</source>
        <translation>{file}：既不是 Motion Panel 日志，也不是 pyserial spy:// 捕获文件：第 {number} 行不是通信日志行：{line!r}；对于 spy://，{hint}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: empty, not a Motion Panel log nor a pyserial spy:// capture (spy&apos;s raw format leaves its file empty); {hint}</source>
        <translation>{file}：文件为空，既不是 Motion Panel 日志，也不是 pyserial spy:// 捕获文件（spy 的 raw 格式会使其文件为空）；{hint}</translation>
    </message>
    <message>
        <location line="-446"/>
        <source>the device reported: {reported}</source>
        <translation>设备报告：{reported}</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>{protocol} device</source>
        <translation>{protocol} 设备</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device did not report a position (it answered {value})</source>
        <translation>设备未报告位置（其应答为 {value}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device is at ({x:g}, {y:g}, {z:g}) mm, not where its last move ended: its replies are no longer taken as arrival</source>
        <translation>设备位于 ({x:g}, {y:g}, {z:g}) mm，并非上次移动结束的位置：不再将其应答视为已到位</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>{protocol} has no speed limits to report</source>
        <translation>{protocol} 没有可报告的速度限值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed {speed:g} refused: the speed must be a positive number</source>
        <translation>速度 {speed:g} 被拒绝：速度必须为正数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed {speed:g} {unit} refused: the device allows {low:g} to {high:g} {unit}</source>
        <translation>速度 {speed:g} {unit} 被拒绝：设备允许 {low:g} 至 {high:g} {unit}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed {speed:g} {unit} written, but this firmware times its steps from its step delays (15, 16) alone: moves go at {real:.3f} {unit}</source>
        <translation>速度 {speed:g} {unit} 已写入，但此固件仅根据其步进延时（15、16）确定步进时序：实际移动速度为 {real:.3f} {unit}</translation>
    </message>
    <message>
        <location line="-36"/>
        <source>move to ({x:g}, {y:g}, {z:g}) mm</source>
        <translation>移动到 ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>jog by ({dx:g}, {dy:g}, {dz:g}) {unit}</source>
        <translation>点动 ({dx:g}, {dy:g}, {dz:g}) {unit}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no way to go home</source>
        <translation>{protocol} 无法回原点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>go home</source>
        <translation>回原点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no set-home command</source>
        <translation>{protocol} 没有设置原点命令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what} refused: home is outside the travel limits</source>
        <translation>已拒绝{what}：原点位于行程限位之外</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no arc moves</source>
        <translation>{protocol} 不支持圆弧移动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>arc</source>
        <translation>圆弧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no dwell</source>
        <translation>{protocol} 不支持延时</translation>
    </message>
    <message>
        <location line="-19"/>
        <source>stopped at ({x:g}, {y:g}, {z:g}) mm</source>
        <translation>已停止于 ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the move to {target} did not end within {seconds:.1f} s</source>
        <translation>前往 {target} 的移动未在 {seconds:.1f} s 内结束</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no protocol to read them with</source>
        <translation>没有可用于解读它们的协议</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>program point {number}</source>
        <translation>程序第 {number} 个点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw bytes refused: {protocol} cannot read them as a command ({reason}), so they cannot be checked against the travel limits ({box}); send them with force to send them anyway</source>
        <translation>原始字节被拒绝：{protocol} 无法将其解读为命令（{reason}），因此无法对照行程限位（{box}）进行检查；若仍要发送，请使用 force 强制发送</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw bytes refused: they hold {count} commands, {moves} of them moves; send a move alone, so that it is checked and followed to its end</source>
        <translation>原始字节被拒绝：其中包含 {count} 条命令，其中 {moves} 条是移动；请单独发送一条移动，以便对其进行检查并跟踪至结束</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw move {command}</source>
        <translation>原始命令移动 {command}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what}: not a move the panel can check</source>
        <translation>{what}：不是面板能够检查的移动</translation>
    </message>
    <message>
        <location line="+214"/>
        <source>{what} {text!r} is not a number the device accepts: use digits with an optional sign and one decimal point, e.g. -12.5</source>
        <translation>{what} {text!r} 不是设备接受的数字：请使用数字，可带正负号和一个小数点，例如 -12.5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what} {value!r} is not a finite number</source>
        <translation>{what} {value!r} 不是有限数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what} {value:g} is out of range: the device handles at most ±{limit:g}</source>
        <translation>{what} {value:g} 超出范围：设备最多支持 ±{limit:g}</translation>
    </message>
    <message>
        <location line="-203"/>
        <source>{source}: not a parameter profile: {error}</source>
        <translation>{source}：不是参数配置文件：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: not a parameter profile: a number too long</source>
        <translation>{source}：不是参数配置文件：数字过长</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: not a parameter profile: nested too deeply</source>
        <translation>{source}：不是参数配置文件：嵌套过深</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: protocol must be a name in quotes</source>
        <translation>{source}：protocol 必须是带引号的名称</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: a profile for {named!r}, not for {protocol!r}</source>
        <translation>{source}：这是 {named!r} 的参数配置文件，不适用于 {protocol!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} (line {line}): unknown key {key!r}</source>
        <translation>{source}（第 {line} 行）：未知键 {key!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: unknown key {key!r}</source>
        <translation>{source}：未知键 {key!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no [parameters] table with values in it</source>
        <translation>{source}：没有含值的 [parameters] 表</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {line}</source>
        <translation>{source} 第 {line} 行</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: unknown parameter {name!r} for {protocol}</source>
        <translation>{where}：未知的 {protocol} 参数 {name!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {error}</source>
        <translation>{where}：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {name}: not a number the device takes ({range})</source>
        <translation>{where}：{name}：不是设备接受的数字（{range}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: only firmware outputs ({names}), which a profile does not write</source>
        <translation>{source}：只有固件输出参数（{names}），配置文件不会写入这些参数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>profile</source>
        <translation>参数配置文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot write the profile {path}: {error}</source>
        <translation>无法写入参数配置文件 {path}：{error}</translation>
    </message>
    <message>
        <location line="+190"/>
        <source>{low} to {high} in steps of {step}</source>
        <translation>{low} 至 {high}，步进 {step}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{low} to {high} (whole numbers)</source>
        <translation>{low} 至 {high}（整数）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{low} to {high}</source>
        <translation>{low} 至 {high}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: {value!r} is not a number ({range})</source>
        <translation>{name}：{value!r} 不是数字（{range}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: {value} refused: {range}</source>
        <translation>{name}：{value} 被拒绝：允许 {range}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: {value} refused: the device takes {range}</source>
        <translation>{name}：{value} 被拒绝：设备接受 {range}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>this protocol has no parameters</source>
        <translation>此协议没有参数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown parameter {name!r} (did you mean {close}?): use a name or an id 1..{count}; &apos;motionctl ... param list&apos; lists them</source>
        <translation>未知参数 {name!r}（是否指 {close}？）：请使用名称或 ID 1..{count}；&apos;motionctl ... param list&apos; 可列出全部参数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown parameter {name!r}: use a name or an id 1..{count}; &apos;motionctl ... param list&apos; lists them</source>
        <translation>未知参数 {name!r}：请使用名称或 ID 1..{count}；&apos;motionctl ... param list&apos; 可列出全部参数</translation>
    </message>
    <message>
        <location line="-197"/>
        <source>its frames carry absolute targets, so a relative move needs the position: Set Home where the stage stands, Home, or move to an absolute point first (in the panel, or motionctl set-home, home or move X Y Z)</source>
        <translation>其帧携带的是绝对目标，因此相对移动需要知道位置：请先在平台当前所在处设为原点、回原点，或移动到一个绝对点（在面板中，或用 motionctl set-home、home 或 move X Y Z）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Home or Set Home (in the panel, or motionctl home / set-home) to start counting</source>
        <translation>请回原点或设为原点（在面板中，或用 motionctl home / set-home）以开始计数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Set Home where the stage stands (in the panel, or motionctl set-home) to start counting; with no home move of its own, Home needs a count too</source>
        <translation>请在平台当前所在处设为原点（在面板中，或用 motionctl set-home）以开始计数；设备自身没有回原点移动，因此回原点也需要位置计数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command} refused: position unknown: {protocol} cannot be asked where it is and no commanded position is kept for this port; {how}</source>
        <translation>{command} 被拒绝：位置未知：无法向 {protocol} 查询其位置，且此端口没有保存指令位置；{how}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command} refused: position unknown: {protocol} cannot be asked where it is and no position is counted for this port; {how}</source>
        <translation>{command} 被拒绝：位置未知：无法向 {protocol} 查询其位置，且此端口没有位置计数；{how}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position unknown: {protocol} cannot be asked where it is and no commanded position is kept for this port; {how}</source>
        <translation>位置未知：无法向 {protocol} 查询其位置，且此端口没有保存指令位置；{how}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position unknown: {protocol} cannot be asked where it is and no position is counted for this port; {how}</source>
        <translation>位置未知：无法向 {protocol} 查询其位置，且此端口没有位置计数；{how}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>this firmware reads the digits as µm whatever the type letter ({kind} is not read): the stage moves X {x:.3f} mm, Y {y:.3f} mm</source>
        <translation>无论类型字母为何，此固件都将数字读作 µm（不会读取 {kind}）：平台移动 X {x:.3f} mm，Y {y:.3f} mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no identity query: the device cannot be asked what it is</source>
        <translation>{protocol} 没有身份查询命令：无法查询设备的身份</translation>
    </message>
    <message>
        <location line="+367"/>
        <source>{where}: {name} {value!r} is not a number</source>
        <translation>{where}：{name} {value!r} 不是数字</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {name} is not a finite float32 number</source>
        <translation>{where}：{name} 不是有限的 float32 数</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>{where}: {name} {value!r} is not a finite float32 number</source>
        <translation>{where}：{name} {value!r} 不是有限的 float32 数</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>{where}: speed {speed:g} mm/s must be above 0</source>
        <translation>{where}：速度 {speed:g} mm/s 必须大于 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {line}: not CSV: {error}</source>
        <translation>{source} 第 {line} 行：不是 CSV：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {line}: the header must name x, y, z and speed (got nothing)</source>
        <translation>{source} 第 {line} 行：表头必须包含 x、y、z 和 speed（实际为空）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {line}: the header must name x, y, z and speed (got {columns})</source>
        <translation>{source} 第 {line} 行：表头必须包含 x、y、z 和 speed（实际为 {columns}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {line}: {count} values, expected 4</source>
        <translation>{source} 第 {line} 行：有 {count} 个值，应为 4 个</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no header line (x,y,z,speed)</source>
        <translation>{source}：没有表头行（x,y,z,speed）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no points</source>
        <translation>{source}：没有点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {line}: not JSON ({reason})</source>
        <translation>{source} 第 {line} 行：不是 JSON（{reason}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: not JSON the panel reads (a number too long)</source>
        <translation>{source}：不是面板可读取的 JSON（数字过长）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: not JSON the panel reads (nested too deeply)</source>
        <translation>{source}：不是面板可读取的 JSON（嵌套过深）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no &quot;points&quot; list</source>
        <translation>{source}：没有 &quot;points&quot; 列表</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: expected [x, y, z, speed]</source>
        <translation>{where}：应为 [x, y, z, speed]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} point {number}</source>
        <translation>{source} 第 {number} 个点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: more than {count} points</source>
        <translation>{source}：点数超过 {count} 个</translation>
    </message>
    <message>
        <location line="-45"/>
        <source>program</source>
        <translation>程序文件</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>cannot write the program {path}: {error}</source>
        <translation>无法写入程序 {path}：{error}</translation>
    </message>
    <message>
        <location line="-173"/>
        <source>this looks like a {found} controller, not {expected}</source>
        <translation>这看起来是 {found} 控制器，而不是 {expected}</translation>
    </message>
    <message>
        <location line="-369"/>
        <source>--device names a device of a bench: give --bench FILE</source>
        <translation>--device 指定的是工作台中的设备：请给出 --bench 文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>--port and --bench both name the device: give one of them</source>
        <translation>--port 和 --bench 都指定了设备：只给出其中一个</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{bench} has {count} devices: choose one with --device ({names})</source>
        <translation>{bench} 有 {count} 台设备：用 --device 选择一台（{names}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{bench} has no device {name!r} (it has {names})</source>
        <translation>{bench} 没有设备 {name!r}（它有 {names}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>--protocol {typed} disagrees with the bench: {name} is {protocol}</source>
        <translation>--protocol {typed} 与工作台不符：{name} 是 {protocol}</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>{what} {text!r} refused: a whole number is needed</source>
        <translation>{what} {text!r} 被拒绝：需要整数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>radius {radius:g} mm refused: it must be above 0</source>
        <translation>半径 {radius:g} mm 被拒绝：必须大于 0</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;{command}&apos; is a {owner} command, not {protocol}&apos;s</source>
        <translation>“{command}”是 {owner} 的命令，不是 {protocol} 的</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>{axis} {value:g} mm refused: outside {low:g}..{high:g} mm (travel limits)</source>
        <translation>{axis} {value:g} mm 被拒绝：超出 {low:g}..{high:g} mm（行程限制）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the stage is not connected: connect it first</source>
        <translation>平台未连接：请先连接</translation>
    </message>
    <message>
        <location line="+136"/>
        <source>{setting} {value} refused: {minimum:g} to {maximum:g} {unit}</source>
        <translation>{setting} {value} 被拒绝：允许 {minimum:g} 至 {maximum:g} {unit}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no setting {name!r}</source>
        <translation>{protocol} 没有设置项 {name!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no wire variants (got {name!r})</source>
        <translation>{protocol} 没有线路变体（收到 {name!r}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} has no variant {name!r} (variants: {known})</source>
        <translation>{protocol} 没有变体 {name!r}（可用变体：{known}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{protocol} moves are linear only (got {kind!r})</source>
        <translation>{protocol} 只支持直线移动（收到 {kind!r}）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>{protocol} cannot read sent frames</source>
        <translation>{protocol} 无法解读发送的帧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the last {count} bytes are not a whole frame: the device would wait for the rest</source>
        <translation>最后 {count} 个字节不是完整的帧：设备会等待其余部分</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no whole frame in {count} bytes</source>
        <translation>{count} 个字节中没有完整的帧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} coordinate</source>
        <translation>{axis} 坐标</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} distance</source>
        <translation>{axis} 距离</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a coordinate</source>
        <translation>坐标</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed {speed:g} mm/s refused: the speed must be positive</source>
        <translation>速度 {speed:g} mm/s 被拒绝：速度必须为正数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw command refused: COXIRIS takes ASCII text only</source>
        <translation>原始命令被拒绝：COXIRIS 只接受 ASCII 文本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw command refused: one line at a time (it contains a line break)</source>
        <translation>原始命令被拒绝：每次只能发送一行（其中含有换行符）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>raw command refused: it is empty, and the device ignores blank lines</source>
        <translation>原始命令被拒绝：命令为空，设备会忽略空行</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>COXIRIS has no command for {command}</source>
        <translation>COXIRIS 没有对应 {command} 的命令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>command refused: {length} characters, the device takes at most {most} ({start}...)</source>
        <translation>命令被拒绝：{length} 个字符，设备最多接受 {most} 个（{start}...）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device reported {what} as {text!r}, which is not a number</source>
        <translation>设备报告的{what}为 {text!r}，不是数字</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device reported {what} as {text!r}</source>
        <translation>设备报告的{what}为 {text!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device does not know the command {name!r}</source>
        <translation>设备不认识命令 {name!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device refused the command: {error}</source>
        <translation>设备拒绝了该命令：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>expected DONE {command}, got {event}</source>
        <translation>应为 DONE {command}，收到 {event}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position reply {data!r} does not hold three numbers</source>
        <translation>位置应答 {data!r} 不包含三个数字</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speeds are reported rounded to whole mm/s</source>
        <translation>报告的速度四舍五入到整数 mm/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>positions are reported to 0.01 mm</source>
        <translation>报告的位置精确到 0.01 mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>non-ASCII bytes in a COXIRIS line: {bytes}</source>
        <translation>COXIRIS 行中含有非 ASCII 字节：{bytes}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>line refused: {length} characters, the device takes at most {most}</source>
        <translation>行被拒绝：{length} 个字符，设备最多接受 {most} 个</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{line!r} has no line end: the device would wait for the rest</source>
        <translation>{line!r} 没有行尾符：设备会等待其余部分</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an empty line: the device ignores it</source>
        <translation>空行：设备会忽略它</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>non-ASCII bytes: COXIRIS takes ASCII text only</source>
        <translation>非 ASCII 字节：COXIRIS 只接受 ASCII 文本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} {params!r} is not three numbers as the firmware reads them</source>
        <translation>按固件的解析方式，{name} {params!r} 不是三个数字</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Motor steps per turn</source>
        <translation>电机每转步数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Motor steps per millimetre</source>
        <translation>电机每毫米步数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Motor control pin {pin} (-1: none)</source>
        <translation>电机控制引脚 {pin}（-1：无）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moves back to 0 by a relative move: the board has no homing</source>
        <translation>通过相对移动回到 0：控制板没有回原点功能</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no completion message: moves are estimated from speed and steps</source>
        <translation>没有完成消息：移动根据速度和步数估算</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the version and firmware name (is a Firmata board on this port?)</source>
        <translation>版本和固件名称（此端口上是否连接了 Firmata 控制板？）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed (rpm)</source>
        <translation>转速 (rpm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>steps per revolution</source>
        <translation>每转步数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pin</source>
        <translation>引脚</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>steps</source>
        <translation>步</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>capability response</source>
        <translation>能力响应</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>analog mapping</source>
        <translation>模拟引脚映射</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>version request</source>
        <translation>版本查询</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>firmware name request</source>
        <translation>固件名称查询</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>STEPPER_LIBRARY_VERSION request</source>
        <translation>STEPPER_LIBRARY_VERSION 查询</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what} {value} refused: the stepper takes {low} to {high}</source>
        <translation>{what} {value} 被拒绝：步进电机接受 {low} 至 {high}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the board answered: {error}</source>
        <translation>控制板应答：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{distance:g} mm refused: the motor moves in steps of {step:g} mm ({per_mm:g} steps/mm)</source>
        <translation>{distance:g} mm 被拒绝：电机每步移动 {step:g} mm（{per_mm:g} steps/mm）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the Firmata stepper is one axis (X): Y and Z must be 0</source>
        <translation>Firmata 步进电机只有一个轴 (X)：Y 和 Z 必须为 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{count} pins refused: a stepper has 2 or 4 pins</source>
        <translation>{count} 个引脚被拒绝：步进电机有 2 个或 4 个引脚</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmata has no message for {command}</source>
        <translation>Firmata 没有对应 {command} 的消息</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an empty Firmata message</source>
        <translation>空的 Firmata 消息</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmata protocol {major}.{minor}</source>
        <translation>Firmata 协议 {major}.{minor}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>analog pin {pin}: {value}</source>
        <translation>模拟引脚 {pin}：{value}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>digital port {port}: {bits:08b}</source>
        <translation>数字端口 {port}：{bits:08b}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>message {bytes}</source>
        <translation>消息 {bytes}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SysEx {command:#04x}</source>
        <translation>SysEx {command:#04x}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>STEPPER_CONFIGURE {steps} steps/rev, pins {pins}</source>
        <translation>STEPPER_CONFIGURE {steps} steps/rev，引脚 {pins}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>STEPPER_STEP {rpm} rpm, {steps} steps forward</source>
        <translation>STEPPER_STEP {rpm} rpm，正转 {steps} 步</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>STEPPER_STEP {rpm} rpm, {steps} steps reverse</source>
        <translation>STEPPER_STEP {rpm} rpm，反转 {steps} 步</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a STEPPER_STEP of {count} data bytes, not 6</source>
        <translation>STEPPER_STEP 有 {count} 个数据字节，而不是 6 个</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>framing</source>
        <translation>帧格式错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>checksum</source>
        <translation>校验和错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown command</source>
        <translation>未知命令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bad arguments</source>
        <translation>参数错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>queue full</source>
        <translation>队列已满</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>undocumented</source>
        <translation>文档未记录</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error {code} ({meaning}) for {command}</source>
        <translation>{command} 出错 {code}（{meaning}）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>speed {speed:g} mm/s refused: it must be above 0</source>
        <translation>速度 {speed:g} mm/s 被拒绝：必须大于 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the position reply holds {count} numbers, not 3</source>
        <translation>位置应答包含 {count} 个数字，而不是 3 个</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the status reply holds {count} numbers, not 2</source>
        <translation>状态应答包含 {count} 个数字，而不是 2 个</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>undocumented code {code}</source>
        <translation>文档未记录的代码 {code}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command}: the device answered error {code} ({meaning})</source>
        <translation>{command}：设备应答错误 {code}（{meaning}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>moves are queued on the device; the position is read back while they run</source>
        <translation>移动在设备上排队执行；执行期间会回读位置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The next queued frame&apos;s number (0: random)</source>
        <translation>下一个排队帧的编号（0：随机）</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>dwell {ms} ms refused: the field is an int16 (0 to 32767)</source>
        <translation>延时 {ms} ms 被拒绝：该字段为 int16（0 至 32767）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a queued frame holds 1 to {most} queued instructions</source>
        <translation>一个排队帧包含 1 至 {most} 条排队指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the laser link has no instruction for {command}</source>
        <translation>激光链路没有对应 {command} 的指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MOVE_LINEAR with {count} float values, not x, y, z and speed</source>
        <translation>MOVE_LINEAR 含 {count} 个浮点值，而不是 x、y、z 和 speed</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>word {word:#04x}</source>
        <translation>字 {word:#04x}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>frame {number} ({words} ×{count})</source>
        <translation>帧 {number}（{words} ×{count}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>frame {number} ({words})</source>
        <translation>帧 {number}（{words}）</translation>
    </message>
    <message>
        <location line="-28"/>
        <source>a field holds 1 to 255 values, not {count}</source>
        <translation>一个字段包含 1 至 255 个值，而不是 {count} 个</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{value!r} is not one ASCII character</source>
        <translation>{value!r} 不是单个 ASCII 字符</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{value} does not fit a float32</source>
        <translation>{value} 超出 float32 的范围</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{value} does not fit a {kind} ({low} to {high})</source>
        <translation>{value} 超出 {kind} 的范围（{low} 至 {high}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>command word {word:#04x} is outside 0x01..0x7F</source>
        <translation>命令字 {word:#04x} 不在 0x01..0x7F 范围内</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>byte {index}: {byte:#04x} where a command word was expected</source>
        <translation>字节 {index}：应为命令字，却是 {byte:#04x}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>byte {index}: a {kind} field without its count</source>
        <translation>字节 {index}：{kind} 字段缺少其计数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>byte {index}: {count} {kind} values run past the data</source>
        <translation>字节 {index}：{count} 个 {kind} 值超出了数据末尾</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Encoder ticks per millimetre</source>
        <translation>每毫米编码器计数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moves back to (0, 0, 0) with a Linear frame: the device has no homing</source>
        <translation>用 Linear 帧回到 (0, 0, 0)：设备没有回原点功能</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write-only: positions are commanded, completion estimated from distance and speed</source>
        <translation>只写：位置为指令值，完成时间根据距离和速度估算</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed {axis}</source>
        <translation>速度 {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>centre {axis}</source>
        <translation>圆心 {axis}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>radius</source>
        <translation>半径</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>angular speed</source>
        <translation>角速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dwell</source>
        <translation>延时</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{field} {value:g} {unit} refused: a pi-frame field holds {low} to {high}</source>
        <translation>{field} {value:g} {unit} 被拒绝：pi-frame 字段的取值为 {low} 至 {high}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{field} {distance:g} mm refused: the device moves in ticks of {tick:g} mm ({per_mm:g} ticks/mm)</source>
        <translation>{field} {distance:g} mm 被拒绝：设备每个计数移动 {tick:g} mm（{per_mm:g} ticks/mm）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{field} {distance:g} mm refused: {ticks} ticks do not fit 16 bits ({low:g} to {high:g} mm at {per_mm:g} ticks/mm)</source>
        <translation>{field} {distance:g} mm 被拒绝：{ticks} 个计数超出 16 位范围（{per_mm:g} ticks/mm 时为 {low:g} 至 {high:g} mm）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pi-frame has no frame for {command}</source>
        <translation>pi-frame 没有对应 {command} 的帧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a {length}-byte frame</source>
        <translation>一个 {length} 字节的帧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Linear X={x} Y={y} Z={z} ticks at {sx}/{sy}/{sz} ticks/s</source>
        <translation>Linear X={x} Y={y} Z={z} 计数，速度 {sx}/{sy}/{sz} ticks/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Circular centre ({x}, {y}) radius {radius} ticks, {start:g}° to {end:g}° {turn} at {speed:g}°/s, Z to {z}</source>
        <translation>Circular 圆心 ({x}, {y}) 半径 {radius} 计数，{start:g}° 至 {end:g}° {turn}，速度 {speed:g}°/s，Z 至 {z}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dwell {ms} ms</source>
        <translation>延时 {ms} ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>action {number}</source>
        <translation>动作 {number}</translation>
    </message>
    <message>
        <location line="+81"/>
        <source>move package confirmed</source>
        <translation>移动数据包已确认</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>action accomplished</source>
        <translation>动作已完成</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>package size mismatch</source>
        <translation>数据包长度不符</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid command type</source>
        <translation>无效的命令类型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid motion type</source>
        <translation>无效的运动类型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid direction for the X axis</source>
        <translation>X 轴方向无效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid direction for the Y axis</source>
        <translation>Y 轴方向无效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid set parameter ID</source>
        <translation>无效的设置参数 ID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>parse function error in the firmware</source>
        <translation>固件中的解析函数出错</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid driving mechanism</source>
        <translation>无效的驱动机构</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an error code the documentation does not list</source>
        <translation>文档未列出的错误代码</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{parameter} set</source>
        <translation>{parameter} 已设置</translation>
    </message>
    <message>
        <source>Sets input_speed_steady_x and _y (parameters 21 and 22). This firmware revision times its steps from step_delay_instantaneous (15, 16) only, so moves keep their pace.</source>
        <translation type="vanished">设置 input_speed_steady_x 和 _y（参数 21 和 22）。此固件版本仅根据 step_delay_instantaneous（15、16）确定步进时序，因此移动速度保持不变。</translation>
    </message>
    <message>
        <location line="-45"/>
        <source>Visiomex has no homing at this revision: Home moves back to (0, 0) by a relative move from the position the panel counted</source>
        <translation>此版本的 Visiomex 没有回原点功能：回原点时从面板累计的位置通过相对移动回到 (0, 0)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no read-back: the panel keeps what was last written</source>
        <translation>无法回读：面板保存上次写入的值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>positions are commanded, and confirmed by FA0001 when the move ends</source>
        <translation>位置为指令值，移动结束时由 FA0001 确认</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a reply comes 1 s after a packet: the firmware waits for 1 s of silence</source>
        <translation>应答在数据包发出 1 s 后到达：固件要等待 1 s 的静默</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>parameter {number} set</source>
        <translation>参数 {number} 已设置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>feedback code {code} is not documented</source>
        <translation>反馈代码 {code} 在文档中没有记录</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command}: the device answered {code} ({meaning}); this firmware revision runs the move anyway</source>
        <translation>{command}：设备应答 {code}（{meaning}）；此固件版本仍会执行该移动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command}: the device answered {code} ({meaning})</source>
        <translation>{command}：设备应答 {code}（{meaning}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{command}: expected {wanted}, got {code}</source>
        <translation>{command}：应为 {wanted}，收到 {code}</translation>
    </message>
    <message>
        <location line="-46"/>
        <source>18-character packets at 9600 baud, as the seed documents</source>
        <translation>18 字符数据包，9600 波特，与原始资料所述一致</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the seed&apos;s packets; feedback lines start with &apos;&gt;&apos;</source>
        <translation>原始资料中的数据包；反馈行以 &apos;&gt;&apos; 开头</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>12-character packets at 115200 baud, moves in mm, D goes home</source>
        <translation>12 字符数据包，115200 波特，移动单位为 mm，D 回原点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Visiomex moves are relative: the panel sends the distance to go</source>
        <translation>Visiomex 的移动为相对移动：面板发送待移动的距离</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the speed is parameters 21 and 22: it is sent as two sets</source>
        <translation>速度即参数 21 和 22：分两次设置发送</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Visiomex has no packet for {command}</source>
        <translation>Visiomex 没有对应 {command} 的数据包</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>move kind {kind!r} refused: Visiomex moves are {kinds}</source>
        <translation>移动类型 {kind!r} 被拒绝：Visiomex 的移动类型为 {kinds}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z {distance:g} mm refused: the Visiomex controller has X and Y only</source>
        <translation>Z {distance:g} mm 被拒绝：Visiomex 控制器只有 X 和 Y 轴</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} {value:g} {unit} refused: this device moves in 1 µm</source>
        <translation>{axis} {value:g} {unit} 被拒绝：此设备的移动单位为 1 µm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} {value:g} {unit} refused: this device moves in whole {unit}</source>
        <translation>{axis} {value:g} {unit} 被拒绝：此设备只能按整数{unit}移动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} {value:g} {unit} refused: one move goes at most {most} {unit} per axis ({digits} digits)</source>
        <translation>{axis} {value:g} {unit} 被拒绝：单次移动每轴最多 {most} {unit}（{digits} 位数字）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>packet refused: Visiomex takes ASCII characters only</source>
        <translation>数据包被拒绝：Visiomex 只接受 ASCII 字符</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>packet refused: it is empty</source>
        <translation>数据包被拒绝：数据包为空</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>packet refused: {length} characters, a Visiomex packet has {most} (a line ending counts too)</source>
        <translation>数据包被拒绝：{length} 个字符，Visiomex 数据包为 {most} 个（行结束符也计算在内）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>non-ASCII bytes in a Visiomex line: {bytes}</source>
        <translation>Visiomex 行中含有非 ASCII 字节：{bytes}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>that packet gets no reply: send it from the console instead</source>
        <translation>该数据包没有应答：请改从控制台发送</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>packet {packet}</source>
        <translation>数据包 {packet}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set {parameter} = {value}</source>
        <translation>设置 {parameter} = {value}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>move linear X {x} Y {y}</source>
        <translation>直线移动 X {x} Y {y}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>move rotational X {x} Y {y}</source>
        <translation>旋转移动 X {x} Y {y}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>move steps X {x} Y {y}</source>
        <translation>按步数移动 X {x} Y {y}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>move {kind} X {x} Y {y}</source>
        <translation>移动 {kind} X {x} Y {y}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>packet {packet!r}</source>
        <translation>数据包 {packet!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>move packet {packet!r} is not as the protocol documents</source>
        <translation>移动数据包 {packet!r} 与协议文档不符</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{packet} (set {parameter})</source>
        <translation>{packet}（设置 {parameter}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the firmware forces driving_mechanism to 1 after every set</source>
        <translation>每次设置后固件都会将 driving_mechanism 强制设为 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the firmware recomputes {parameter} after every set: this value will not stay (it holds {held:g})</source>
        <translation>每次设置后固件都会重新计算 {parameter}：此值不会保留（设备当前值为 {held:g}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the firmware recomputes {parameter} at every move: this value will not stay</source>
        <translation>每次移动时固件都会重新计算 {parameter}：此值不会保留</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>this firmware revision reads {parameter} only at boot: moves do not change until the device restarts</source>
        <translation>此固件版本仅在启动时读取 {parameter}：在设备重启之前，移动不会改变</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>this firmware revision never reads {parameter}: moves do not change</source>
        <translation>此固件版本从不读取 {parameter}：移动不会改变</translation>
    </message>
    <message>
        <location line="-75"/>
        <source>Steps per move</source>
        <translation>每次移动的步数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X: 1 mm = {x1}, 10 mm = {x10} · Y: 1 mm = {y1}, 10 mm = {y10} (truncated: the firmware counts in 32-bit floats)</source>
        <translation>X：1 mm = {x1}，10 mm = {x10} · Y：1 mm = {y1}，10 mm = {y10}（已截断：固件以 32 位浮点数计数）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{steps} steps, {stepping} s of stepping; FA0001 about {total} s after the packet</source>
        <translation>{steps} 步，步进耗时 {stepping} s；数据包发出后约 {total} s 收到 FA0001</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{text}; after a move in which Y stepped, {later} s (X&apos;s low phase is Y&apos;s last delay, {delay} µs: the ramps do not restore the delays)</source>
        <translation>{text}；在 Y 轴有步进的移动之后为 {later} s（X 的低电平阶段取 Y 的最后延时 {delay} µs：斜坡不会恢复延时）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A 10 mm X move</source>
        <translation>X 轴移动 10 mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no: the firmware&apos;s Y loop runs the ramp count (R_y = 0 with these values), not the {asked} steps a 10 mm move asks for; set 22 and 24 so that the ramp length is above 0 (e.g. 22 = 6000, 24 = 1)</source>
        <translation>不移动：固件的 Y 循环执行的是斜坡计数（按这些值 R_y = 0），而不是 10 mm 移动所需的 {asked} 步；请设置 22 和 24，使斜坡长度大于 0（例如 22 = 6000，24 = 1）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{runs} of the {asked} steps of a 10 mm Y move, {seconds} s: the firmware&apos;s Y loop runs the ramp count R_y (at most the ramp length {ramp}), not the distance, and speeds up without slowing down</source>
        <translation>10 mm Y 轴移动所需 {asked} 步中的 {runs} 步，{seconds} s：固件的 Y 循环按斜坡计数 R_y（至多为斜坡长度 {ramp}）执行，而不是按距离，且只加速不减速</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y moves</source>
        <translation>Y 轴移动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none: the ramp length is 0 on both axes (it follows 21 ÷ 23 and 13 - 11); every X step takes 15 high plus 16 low</source>
        <translation>无：两轴的斜坡长度均为 0（由 21 ÷ 23 和 13 - 11 决定）；每个 X 步耗时为 15 高电平加 16 低电平</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X over {x} steps, Y over {y} steps, between 13/14 (slow) and 11/12 (fast)</source>
        <translation>X 历经 {x} 步，Y 历经 {y} 步，介于 13/14（慢）和 11/12（快）之间</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ramps</source>
        <translation>斜坡</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not used</source>
        <translation>未使用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{names}: the values in the table differ from power-on, but this firmware does not use them</source>
        <translation>{names}：表中的值与上电值不同，但此固件不使用它们</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Overwritten after every set</source>
        <translation>每次设置后被覆盖</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{ids}: the firmware recomputes them; a written value does not stay</source>
        <translation>{ids}：固件会重新计算它们；写入的值不会保留</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Overwritten at every move</source>
        <translation>每次移动时被覆盖</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{ids}: the ramp counts of the last move</source>
        <translation>{ids}：上次移动的斜坡计数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Never read</source>
        <translation>从不读取</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{ids}: writing them changes nothing (27 is forced to 1 after every set)</source>
        <translation>{ids}：写入它们不会改变任何东西（每次设置后 27 都会被强制设为 1）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read only at boot</source>
        <translation>仅在启动时读取</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{ids}: the cycle length ({cycle} mm) is taken from them at power-on, when they hold their power-on values again: writing them changes no move</source>
        <translation>{ids}：周期长度（{cycle} mm）在上电时取自这些参数，而此时它们已恢复为上电值：写入它们不会改变任何移动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the firmware recomputes {id} after every set: this value will not stay</source>
        <translation>每次设置后固件都会重新计算 {id}：此值不会保留</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the firmware recomputes {id} at every move: this value will not stay</source>
        <translation>每次移动时固件都会重新计算 {id}：此值不会保留</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the firmware forces 27 to 1 after every set: this value will not stay</source>
        <translation>每次设置后固件都会将 27 强制设为 1：此值不会保留</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>this firmware never reads {id:02d}: writing it changes nothing</source>
        <translation>此固件从不读取 {id:02d}：写入它不会改变任何东西</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a move with ramps (ramp length above 0) leaves {id} at the ramp&apos;s last delay: this value stays only until then</source>
        <translation>带斜坡的移动（斜坡长度大于 0）会将 {id} 留在斜坡的最后延时：此值只保留到那时</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>this firmware reads {id:02d} only at boot, when it holds {value} again: writing it changes no move</source>
        <translation>此固件仅在启动时读取 {id:02d}，而那时它已恢复为 {value}：写入它不会改变任何移动</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Current step delay, {axis} axis (left by the firmware&apos;s ramps; this revision times an X step as 15 high plus 16 low, a Y step as 16 twice)</source>
        <translation>{axis} 轴当前步进延时（由固件的斜坡留下；此版本中一个 X 步的时长为 15 高电平加 16 低电平，一个 Y 步为两倍的 16）</translation>
    </message>
    <message>
        <source>this firmware revision reads {parameter} only at boot (and keeps pulley values divided by 4): moves do not change until the firmware is fixed</source>
        <translation type="vanished">此固件版本仅在启动时读取 {parameter}（且保存的带轮数值被除以 4）：在固件修复之前，移动不会改变</translation>
    </message>
    <message>
        <source>Note</source>
        <translation type="vanished">注意</translation>
    </message>
    <message>
        <source>this firmware revision moves by the cycle it computed at boot (10 mm lead screw), whatever 01-04 and 27 say</source>
        <translation type="vanished">此固件版本按启动时计算的周期（10 mm 丝杠）移动，与 01-04 和 27 的设置无关</translation>
    </message>
    <message>
        <source>{axis}: the cycle ({cycle:g} mm) and the steps per turn ({steps:g}) must both be above 0</source>
        <translation type="vanished">{axis}：周期（{cycle:g} mm）和每转步数（{steps:g}）都必须大于 0</translation>
    </message>
    <message>
        <source>{times} (1 s silence included)</source>
        <translation type="vanished">{times}（含 1 s 静默）</translation>
    </message>
    <message>
        <source>Microsteps per turn</source>
        <translation type="vanished">每转微步数</translation>
    </message>
    <message>
        <source>Per step</source>
        <translation type="vanished">每步</translation>
    </message>
    <message>
        <source>Steps per mm</source>
        <translation type="vanished">每毫米步数</translation>
    </message>
    <message>
        <source>A 10 mm move</source>
        <translation type="vanished">移动 10 mm 耗时</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>Lead-screw pitch of the {axis} axis (mm per turn)</source>
        <translation>{axis} 轴丝杠导程（每转 mm）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Belt pulley diameter of the {axis} axis; sent as mm×10 (38.2 mm -&gt; 000382)</source>
        <translation>{axis} 轴皮带轮直径；以 mm×10 发送（38.2 mm -&gt; 000382）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Full steps per motor turn, {axis} axis</source>
        <translation>{axis} 轴电机每转整步数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Microstepping factor of the {axis} driver</source>
        <translation>{axis} 驱动器的细分倍数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Highest speed allowed on the {axis} axis</source>
        <translation>{axis} 轴允许的最高速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Step delay at the steady speed, {axis} axis (computed by the firmware)</source>
        <translation>{axis} 轴匀速时的步进延时（由固件计算）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Step delay at the lowest speed, {axis} axis</source>
        <translation>{axis} 轴最低速度时的步进延时</translation>
    </message>
    <message>
        <source>Current step delay, {axis} axis (computed by the firmware; this revision times every step from it: one step is twice this delay)</source>
        <translation type="vanished">{axis} 轴当前步进延时（由固件计算；此版本的每一步都按它计时：一步为此延时的两倍）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mean step delay while accelerating, {axis} axis (computed by the firmware)</source>
        <translation>{axis} 轴加速期间的平均步进延时（由固件计算）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Steps spent accelerating, {axis} axis (computed by the firmware)</source>
        <translation>{axis} 轴加速所用步数（由固件计算）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Requested steady speed of the {axis} axis</source>
        <translation>{axis} 轴请求的匀速速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Requested acceleration of the {axis} axis</source>
        <translation>{axis} 轴请求的加速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Duration of the last move, {axis} axis (computed by the firmware)</source>
        <translation>{axis} 轴上次移动的持续时间（由固件计算）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0 belt pulley, 1 lead screw (this firmware forces 1 after every set)</source>
        <translation>0 皮带轮，1 丝杠（每次设置后此固件都会强制设为 1）</translation>
    </message>
    <message>
        <source>protocol {name!r} is not implemented yet</source>
        <translation type="vanished">协议 {name!r} 尚未实现</translation>
    </message>
    <message>
        <location line="-44"/>
        <source>unknown protocol {name!r} (known: {known})</source>
        <translation>未知协议 {name!r}（已知：{known}）</translation>
    </message>
    <message>
        <location line="+105"/>
        <source>{protocol} has no stop command: the device finishes what it was sent</source>
        <translation>{protocol} 没有停止命令：设备会完成已发给它的内容</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timeout {timeout:g} s refused: it must be positive</source>
        <translation>超时 {timeout:g} s 被拒绝：必须为正数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>variant {variant!r} asked for a protocol made as {chosen!r}</source>
        <translation>为按 {chosen!r} 创建的协议请求了变体 {variant!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>baud {baud} refused: a positive number of bits per second</source>
        <translation>波特率 {baud} 被拒绝：应为正数（单位 bit/s）</translation>
    </message>
    <message>
        <location line="+91"/>
        <source>capture with spy&apos;s default hexdump format: spy://PORT?file=FILE, without raw</source>
        <translation>请用 spy 的默认 hexdump 格式捕获：spy://PORT?file=FILE，不加 raw</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>both directions run together, nothing tells TX from RX</source>
        <translation>两个方向的数据混在一起，无法区分 TX 和 RX</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {number}: spy&apos;s raw format is refused ({why}); {hint}</source>
        <translation>{source} 第 {number} 行：不接受 spy 的 raw 格式（{why}）；{hint}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {number}: not a pyserial spy:// hexdump line: {line!r}</source>
        <translation>{source} 第 {number} 行：不是 pyserial spy:// hexdump 行：{line!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source} line {number}: bytes at offset {offset:#06x} of a {direction} call whose earlier lines are missing</source>
        <translation>{source} 第 {number} 行：位于 {direction} 调用偏移 {offset:#06x} 处的字节，但该调用前面的行缺失</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no traffic in it, only control-line events</source>
        <translation>{source}：其中没有通信数据，只有控制信号线事件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{source}: no traffic in it (nor spy&apos;s raw format); {hint}</source>
        <translation>{source}：其中没有通信数据（也不是 spy 的 raw 格式）；{hint}</translation>
    </message>
    <message>
        <location line="-25"/>
        <source>{error} (after {rounds} rounds; {acknowledged} of {total} instructions were acknowledged before it)</source>
        <translation>{error}（经过 {rounds} 轮重试；此前 {total} 条指令中已有 {acknowledged} 条得到确认）</translation>
    </message>
    <message>
        <location line="-179"/>
        <source>protocol {name!r} cannot be loaded: {error}</source>
        <translation>无法加载协议 {name!r}：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>protocol {name!r}: {target} is not a protocol class</source>
        <translation>协议 {name!r}：{target} 不是协议类</translation>
    </message>
    <message>
        <location line="+98"/>
        <source>{source}: {why}</source>
        <translation>{source}：{why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: device {device!r}: {why}</source>
        <translation>{where}：设备 {device!r}：{why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bench file</source>
        <translation>工作台文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{path}: no device {name!r} (the bench has {names})</source>
        <translation>{path}：没有设备 {name!r}（工作台有 {names}）</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>{name}</source>
        <translation>{name}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: more than {count:,} steps (lines, arcs and travel moves)</source>
        <translation>{where}：超过 {count:,} 步（直线、圆弧和空移）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: a coordinate that is not a finite number</source>
        <translation>{where}：坐标不是有限数值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>chord tolerance {tolerance:g} mm must be above 0</source>
        <translation>弦公差 {tolerance:g} mm 必须大于 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DXF drawing</source>
        <translation>DXF 图纸</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: not a drawing the panel reads: {why}</source>
        <translation>{where}：不是面板可读取的图形：{why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: no lines, arcs or curves on the chosen layers</source>
        <translation>{name}：所选图层上没有直线、圆弧或曲线</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: skipped what is not a path: {what}</source>
        <translation>{name}：已跳过非路径的内容：{what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: binary DXF cut short (no EOF at its end)</source>
        <translation>{name}：二进制 DXF 被截断（末尾没有 EOF）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: a DWG drawing, not DXF (save it as DXF)</source>
        <translation>{name}：这是 DWG 图纸，不是 DXF（请另存为 DXF）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: not a DXF drawing the panel reads: {why}</source>
        <translation>{name}：不是面板可读取的 DXF 图纸：{why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: $INSUNITS {value!r} is not a unit code</source>
        <translation>{name}：$INSUNITS {value!r} 不是单位代码</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: no units given ($INSUNITS 0), taken as mm</source>
        <translation>{name}：未指定单位（$INSUNITS 0），按 mm 处理</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: units $INSUNITS {code} the panel cannot convert to mm</source>
        <translation>{name}：面板无法将单位 $INSUNITS {code} 换算为 mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} entity {number} ({kind} on layer {layer}): not a drawing the panel reads: {why}</source>
        <translation>{name} 图元 {number}（图层 {layer} 上的 {kind}）：不是面板可读取的图形：{why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: no layer {layer} with lines, arcs or curves; the drawing&apos;s layers: {layers}</source>
        <translation>{name}：没有包含直线、圆弧或曲线的图层 {layer}；图纸的图层：{layers}</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>{name} line {number}</source>
        <translation>{name} 第 {number} 行</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: a comment opened with ( is not closed</source>
        <translation>{where}：以 ( 开始的注释没有闭合</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word} with R: a full circle needs I/J</source>
        <translation>{where}：{word} 使用 R：整圆需要 I/J</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word}: R {radius:g} mm is less than half the way to the end point ({half:g} mm)</source>
        <translation>{where}：{word}：R {radius:g} mm 小于到终点距离的一半（{half:g} mm）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word}: the feed rate must be above 0</source>
        <translation>{where}：{word}：进给速度必须大于 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word} needs P, the seconds to dwell</source>
        <translation>{where}：{word} 需要 P，即停留的秒数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word}: a dwell cannot be negative</source>
        <translation>{where}：{word}：停留时间不能为负</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word} with no motion mode (G0, G1, G2 or G3) set</source>
        <translation>{where}：{word} 未设置运动模式（G0、G1、G2 或 G3）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: no feed rate (F) set before this {word}</source>
        <translation>{where}：此 {word} 之前未设置进给速度（F）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: no moves and no dwells</source>
        <translation>{name}：没有移动，也没有停留</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word}: arcs in the {plane} plane ({code}) are not supported: only G17 (XY)</source>
        <translation>{where}：{word}：不支持 {plane} 平面（{code}）中的圆弧：仅支持 G17（XY）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word} needs I and J, or R</source>
        <translation>{where}：{word} 需要 I 和 J，或 R</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word}: the centre is {start:g} mm from the start point and {end:g} mm from the end point, not on one circle</source>
        <translation>{where}：{word}：圆心距起点 {start:g} mm，距终点 {end:g} mm，不在同一个圆上</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word}: an arc of radius 0</source>
        <translation>{where}：{word}：半径为 0 的圆弧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word} is not used by anything on the line</source>
        <translation>{where}：{word} 未被该行中的任何内容使用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {first} and {second} cannot be on one line</source>
        <translation>{where}：{first} 和 {second} 不能在同一行</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>{name}: more than {count:,} lines, too many for a program</source>
        <translation>{name}：超过 {count:,} 行，程序过长</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word!r} is not a G-code word (a letter and a number)</source>
        <translation>{where}：{word!r} 不是 G-code 字（一个字母加一个数字）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {word} is not understood</source>
        <translation>{where}：无法理解 {word}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: skipped what the panel does not do: {words} (on {count} of {total} lines)</source>
        <translation>{name}：已跳过面板不支持的内容：{words}（共 {total} 行中的 {count} 行）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>chord tolerance {value:g} mm refused: it must be above 0</source>
        <translation>弦公差 {value:g} mm 被拒绝：必须大于 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: the program moves {axis} to {value:g} mm, an axis the device does not have (it has {axes}); nothing was sent</source>
        <translation>{where}：程序将 {axis} 移动到 {value:g} mm，但设备没有该轴（设备的轴为 {axes}）；未发送任何内容</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>{where}: the program would leave the travel box at ({x:g}, {y:g}, {z:g}) mm ({box}); nothing was sent</source>
        <translation>{where}：程序会在 ({x:g}, {y:g}, {z:g}) mm 处超出行程范围（{box}）；未发送任何内容</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{file}: layers are chosen in DXF files only</source>
        <translation>{file}：只有 DXF 文件才能选择图层</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} entity {number} ({text})</source>
        <translation>{name} 图元 {number}（{text}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} element {number} ({text})</source>
        <translation>{name} 元素 {number}（{text}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} point {number}</source>
        <translation>{name} 点 {number}</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>{where}: speed {speed:g} mm/s refused: the device allows {low:g} to {high:g} mm/s; nothing was sent</source>
        <translation>{where}：速度 {speed:g} mm/s 被拒绝：设备允许 {low:g} 至 {high:g} mm/s；未发送任何内容</translation>
    </message>
    <message>
        <location line="-513"/>
        <source>{command} refused: the stepper is not configured for {port} (the board forgets it at each reset, and none is kept for this port); run motionctl --port {port} --protocol firmata config --steps-per-rev 200 --pins 8 9 with your motor&apos;s steps per revolution and pins (or Configure in the panel&apos;s Stepper setup): it is kept and sent again at each run</source>
        <translation>{command} 被拒绝：{port} 的步进电机尚未配置（控制板每次复位都会丢失该配置，且此端口没有保存的配置）；请运行 motionctl --port {port} --protocol firmata config --steps-per-rev 200 --pins 8 9，并换成您电机的每转步数和引脚（或在面板的“步进电机设置”中点击“配置”）：该配置会被保存，并在每次运行时重新发送</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>{file} names no protocol (no connection note) and no protocol recognises its traffic: give --protocol</source>
        <translation>{file} 未指明协议（没有连接说明），且没有任何协议能识别其通信内容：请指定 --protocol</translation>
    </message>
    <message>
        <location line="+388"/>
        <source>The speed cannot be set here: this firmware revision times its steps from step_delay_instantaneous (15, 16) alone, not from input_speed_steady (21, 22). &quot;device:&quot; is the speed X steps at (15 high plus 16 low a step); change 15 and 16 in the parameter table to change it.</source>
        <translation>此处无法设置速度：此固件版本仅根据 step_delay_instantaneous（15、16）确定步进时序，而不是 input_speed_steady（21、22）。“设备：”是 X 的步进速度（每步 15 高电平加 16 低电平）；要改变它，请在参数表中修改 15 和 16。</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Y will not move: at these parameters the firmware&apos;s Y loop makes no step (it runs the ramp count, 0; set 22 and 24 so that the ramp length is above 0)</source>
        <translation>Y 轴不会移动：按这些参数，固件的 Y 循环一步也不走（它执行的是斜坡计数，即 0；请设置 22 和 24，使斜坡长度大于 0）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y moves {moved:.3f} mm, not {asked:.3f}: the firmware&apos;s Y loop runs the ramp count ({loops} of {steps} steps)</source>
        <translation>Y 轴移动 {moved:.3f} mm，而不是 {asked:.3f}：固件的 Y 循环执行的是斜坡计数（{steps} 步中的 {loops} 步）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} moves {moved:.3f} mm, not {asked:.3f}: whole steps ({steps}), truncated as the firmware counts</source>
        <translation>{axis} 轴移动 {moved:.3f} mm，而不是 {asked:.3f}：按整步计（{steps} 步），按固件的计数方式截断</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>{protocol} reports where it is: it is asked</source>
        <translation>{protocol} 会报告其位置：直接向其查询</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>the program&apos;s moves without a speed would go at the device&apos;s speed, {speed:g} mm/s, outside the {low:g} to {high:g} mm/s it allows: set the speed first; nothing was sent</source>
        <translation>程序中未指定速度的移动将以设备的速度 {speed:g} mm/s 运行，超出其允许的 {low:g} 至 {high:g} mm/s：请先设置速度；未发送任何内容</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: {error}; nothing was sent</source>
        <translation>{where}：{error}；未发送任何内容</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the program was abandoned during a dwell</source>
        <translation>程序在停留期间被放弃</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SVG scale {scale:g} mm per unit must be above 0</source>
        <translation>SVG 缩放比例（每单位 {scale:g} mm）必须大于 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SVG drawing</source>
        <translation>SVG 图纸</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where}: not a shape the panel reads: {why}</source>
        <translation>{where}：不是面板可读取的形状：{why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: no stroked paths or shapes to run</source>
        <translation>{name}：没有可运行的描边路径或形状</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: skipped {what}</source>
        <translation>{name}：已跳过 {what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} line {line}: not SVG: {why}</source>
        <translation>{name} 第 {line} 行：不是 SVG：{why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: not an SVG drawing the panel reads: {why}</source>
        <translation>{name}：不是面板可读取的 SVG 图纸：{why}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: not an SVG drawing (no svg element)</source>
        <translation>{name}：不是 SVG 图纸（没有 svg 元素）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name}: no width and height in mm, cm, in, pt, pc or px; 1 unit taken as {scale:g} mm</source>
        <translation>{name}：没有以 mm、cm、in、pt、pc 或 px 表示的宽度和高度；1 个单位按 {scale:g} mm 计</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>{pattern!r} is not a regular expression: {error}</source>
        <translation>{pattern!r} 不是正则表达式：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{pattern!r} is not valid text</source>
        <translation>{pattern!r} 不是有效的文本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{pattern!r}… is too large a regular expression: {error}</source>
        <translation>{pattern!r}… 正则表达式过大：{error}</translation>
    </message>
    <message>
        <location line="-353"/>
        <source>{url} is not open</source>
        <translation>{url} 未打开</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>writing to {url} failed: {error}</source>
        <translation>写入 {url} 失败：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>writing to {url}: only {written} of {total} bytes sent</source>
        <translation>写入 {url}：{total} 字节中仅发送了 {written} 字节</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reading from {url} failed: {error}</source>
        <translation>从 {url} 读取失败：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name!r} is not a line the host drives (DTR or RTS)</source>
        <translation>{name!r} 不是由主机驱动的信号线（DTR 或 RTS）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{line} cannot be set</source>
        <translation>无法设置 {line}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>setting {line} on {url} failed: {error}</source>
        <translation>设置 {url} 的 {line} 失败：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the server did not confirm the control lines ({what} unanswered); they are set without confirmation (ser2net does not answer when the port it serves has no modem lines, e.g. a pseudo-terminal)</source>
        <translation>服务器未确认控制信号线（{what} 未应答）；这些信号线已设置但未经确认（当 ser2net 所服务的端口没有调制解调器信号线时，例如伪终端，它不会应答）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a break lasts more than 0 and at most {most:g} s</source>
        <translation>中断信号的持续时间须大于 0 且不超过 {most:g} s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no break can be sent</source>
        <translation>无法发送中断信号</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sending a break on {url} failed: {error}</source>
        <translation>在 {url} 上发送中断信号失败：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>break {ms:.0f} ms</source>
        <translation>中断 {ms:.0f} ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reading {line} on {url} failed: {error}</source>
        <translation>读取 {url} 的 {line} 失败：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reading the control lines of {url} failed: {error}</source>
        <translation>读取 {url} 的控制信号线失败：{error}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a TCP socket</source>
        <translation>TCP 套接字</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{url} has no modem control lines ({why}): {what}</source>
        <translation>{url} 没有调制解调器控制线（{why}）：{what}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a pseudo-terminal</source>
        <translation>伪终端</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>its driver has no modem-line control</source>
        <translation>其驱动程序不支持调制解调器控制线</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no port given</source>
        <translation>未指定端口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{url} is in use by another program</source>
        <translation>{url} 正被其他程序使用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot open {url}: {error}</source>
        <translation>无法打开 {url}：{error}</translation>
    </message>
    <message>
        <location line="-67"/>
        <source>travel limits need a range for each of x, y and z</source>
        <translation>行程限位需要为 x、y 和 z 各指定一个范围</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>travel limits for {axis} ({low:g} to {high:g} mm) are not a range: the minimum must be at most the maximum</source>
        <translation>{axis} 的行程限位（{low:g} 至 {high:g} mm）不是有效范围：最小值不得大于最大值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the move</source>
        <translation>移动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{axis} {value:g} mm is outside {low:g}..{high:g} mm</source>
        <translation>{axis} {value:g} mm 超出 {low:g}..{high:g} mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the stage is outside its travel limits: {what} brings it closer ({details})</source>
        <translation>平台位于行程限位之外：{what}使其更接近限位范围（{details}）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what} refused: {details} (travel limits)</source>
        <translation>{what}被拒绝：{details}（行程限位）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{what} clamped to the travel limits: {details}; going to ({x:g}, {y:g}, {z:g}) mm</source>
        <translation>{what}已限制在行程限位内：{details}；改为移动到 ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>travel limits {text!r}: write three ranges in mm, X0:X1,Y0:Y1,Z0:Z1 (e.g. -100:100,-50:50,0:20), or none</source>
        <translation>行程限位 {text!r}：请输入三个以 mm 为单位的范围 X0:X1,Y0:Y1,Z0:Z1（例如 -100:100,-50:50,0:20），或 none</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>travel limits for {axis}: {part!r} is not MIN:MAX in mm (e.g. -100:100)</source>
        <translation>{axis} 的行程限位：{part!r} 不是以 mm 为单位的 MIN:MAX（例如 -100:100）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} {value!r} is not a finite number</source>
        <translation>{name} {value!r} 不是有限数值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{name} {value:g} mm refused: the device works to {resolution:g} mm (the nearest it can do is {nearest} mm)</source>
        <translation>{name} {value:g} mm 被拒绝：设备精度为 {resolution:g} mm（最接近的可用值为 {nearest} mm）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{earlier}; {later}</source>
        <translation>{earlier}；{later}</translation>
    </message>
    <message>
        <location line="+300"/>
        <source>expected a sim:// URL, got {url!r}</source>
        <translation>应为 sim:// URL，收到 {url!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown sim:// option {key!r}</source>
        <translation>未知的 sim:// 选项 {key!r}</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>port must be configured before it can be used</source>
        <translation>端口必须先配置才能使用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>port already open</source>
        <translation>端口已打开</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot open {port}: {error}</source>
        <translation>无法打开 {port}：{error}</translation>
    </message>
    <message>
        <location line="-273"/>
        <source>{where} accepted this connection and closed it at once{said}: another client probably holds the port (ser2net serves one at a time with max-connections: 1); close it there first</source>
        <translation>{where} 接受了此连接后立即将其关闭{said}：可能有其他客户端占用该端口（设置 max-connections: 1 时，ser2net 一次只服务一个客户端）；请先关闭那个客户端</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the server has not reported the modem lines</source>
        <translation>服务器尚未报告调制解调器信号线</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nothing answers at {where} ({error}): is ser2net (or another RFC 2217 server) running there and serving that port?</source>
        <translation>{where} 处无任何应答（{error}）：ser2net（或其他 RFC 2217 服务器）是否在该处运行并提供该端口？</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>{where} answers, but not as an RFC 2217 server: serve the port with ser2net&apos;s `accepter: telnet(rfc2217),tcp,PORT`, or open a raw TCP server as socket://{where}</source>
        <translation>{where} 有应答，但不是 RFC 2217 服务器：请用 ser2net 的 `accepter: telnet(rfc2217),tcp,PORT` 提供该端口，或以 socket://{where} 打开原始 TCP 服务器</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timeout while waiting for option &apos;purge&apos;</source>
        <translation>等待选项 &apos;purge&apos; 时超时</translation>
    </message>
    <message>
        <location line="-34"/>
        <source>no axis {axis!r}: x, y or z</source>
        <translation>没有轴 {axis!r}：应为 x、y 或 z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>work zero at home (work = machine)</source>
        <translation>工件零点位于原点（工件坐标 = 机床坐标）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>work zero at ({x:g}, {y:g}, {z:g}) mm machine</source>
        <translation>工件零点位于机床坐标 ({x:g}, {y:g}, {z:g}) mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>work zero {text!r} is not three numbers x,y,z</source>
        <translation>工件零点 {text!r} 不是三个数字 x,y,z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>work zero {text!r} is not three finite numbers x,y,z</source>
        <translation>工件零点 {text!r} 不是三个有限数值 x,y,z</translation>
    </message>
</context>
</TS>
