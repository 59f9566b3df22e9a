using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.StlGen.Options;

/// <summary>
/// What the handler is generated for. Values are taken as given; <see cref="Diagnostics.HandlerOptionsCheck"/> reports the
/// impossible ones with stable IDs instead of throwing. Unset block numbers and the buffer start get defaults that
/// keep out of an existing program's way (see <see cref="HandlerDefaults"/>).
/// </summary>
public sealed record HandlerOptions
{
    public required CpuProfile Cpu { get; init; }

    /// <summary>The PLC's port 0 or 1 (port 1 only on CPU 224XP and 226).</summary>
    public int Port { get; init; }

    /// <summary>Freeport baud rate; must have an SMB30/SMB130 code on this CPU (57600/115200 only on Current CPUs).</summary>
    public int BaudRate { get; init; } = 9600;

    public Parity Parity { get; init; } = Parity.None;

    /// <summary>7 or 8 (SMB30 bit 5).</summary>
    public int DataBits { get; init; } = 8;

    /// <summary>Always 1 in Freeport (seed 002 Table C-11: one stop bit for every configuration).</summary>
    public int StopBits { get; init; } = 1;

    /// <summary>RS-485 station address 1-126.</summary>
    public int Station { get; init; } = 1;

    /// <summary>First V byte of the handler's bytes (buffer, work bytes, change copies); null = <see cref="HandlerDefaults.BufferStart"/>.</summary>
    public int? BufferStart { get; init; }

    /// <summary>Bit n set = protocol area code n may be written (2 Q, 3 M, 4 V, 5 SM); bit 1 (I) never.</summary>
    public int WriteMask { get; init; } = HandlerDefaults.WriteMask;

    /// <summary>1-255 ms between the request's end and the reply (SMB34, timed interrupt 0).</summary>
    public int ReplyDelayMs { get; init; } = 5;

    /// <summary>0 = off (SMB87 = 16#E0); otherwise the inter-character timeout in ms (SMB87 = 16#E4, SMW92).</summary>
    public int CharTimeoutMs { get; init; }

    /// <summary>The handler's one subroutine; null = <see cref="HandlerDefaults.FirstSubroutine"/>.</summary>
    public int? FirstSubroutine { get; init; }

    /// <summary>The first of the handler's interrupt routines (<see cref="InterruptRoutines"/>); null = <see cref="HandlerDefaults.FirstInterrupt"/>.</summary>
    public int? FirstInterrupt { get; init; }

    public HandlerBlockNames Names { get; init; } = new();

    /// <summary>
    /// 0-255 V bytes after the work bytes for READ CHANGES copies (docs/protocol-v2.md, "READ CHANGES"); 0 = none, every
    /// READ CHANGES then answers the whole list.
    /// </summary>
    public int CopyBytes { get; init; } = HandlerDefaults.CopyBytes;

    /// <summary>Whether the handler carries 07 STOP; off = no STOP code at all, CMD 07 gets error 05 like any unknown command.</summary>
    public bool AllowStop { get; init; }

    /// <summary>
    /// 3 (binary frames, docs/protocol.md: what the panel speaks; the default) or 2 (hex frames, the previous protocol,
    /// docs/protocol-v2.md: kept for `opanel generate --protocol 2`, `bench link --protocol 2` and the v2 generator's
    /// tests, which ask for it by name). The panel tells a v2 handler to regenerate.
    /// </summary>
    public int Protocol { get; init; } = 3;

    /// <summary>Version 3 only: the compact handler (IDENTIFY, READ, WRITE, WRITE BIT; no list, no STOP).</summary>
    public bool Compact { get; init; }

    /// <summary>
    /// The settings a project fixes for one station: protocol 3, CPU, station address, baud, parity, data and stop bits,
    /// STOP, compact, and V_FIRST when the project records one ("handlerVFirst"; else the top of V).
    /// </summary>
    public static HandlerOptions For(ProjectStation station)
    {
        ArgumentNullException.ThrowIfNull(station);
        return new HandlerOptions
        {
            Protocol = 3,
            Cpu = station.Cpu,
            Station = station.Address.Address,
            BaudRate = station.Link.BaudRate,
            Parity = station.Link.Parity,
            DataBits = station.Link.DataBits,
            StopBits = station.Link.StopBits,
            AllowStop = station.AllowStop,
            Compact = station.Compact,
            BufferStart = station.HandlerVFirst,
        };
    }

    /// <summary>A station of a simulated or real line: its CPU, port, address, write mask and reply delay on <paramref name="serial"/>'s settings; the rest default.</summary>
    public static HandlerOptions ForLine(CpuProfile cpu, int port, int station, int writeMask, int replyDelayMs, SerialSettings serial)
    {
        ArgumentNullException.ThrowIfNull(serial);
        return new HandlerOptions
        {
            Cpu = cpu,
            Port = port,
            BaudRate = serial.BaudRate,
            Parity = serial.Parity,
            DataBits = serial.DataBits,
            Station = station,
            WriteMask = writeMask,
            ReplyDelayMs = replyDelayMs,
        };
    }

    public int EffectiveBufferStart => BufferStart ?? HandlerDefaults.BufferStart(Cpu, CopyBytes);

    /// <summary>Version 3: V_FIRST, by default the top of V for the full or compact shape.</summary>
    public int EffectiveV3First => BufferStart ?? HandlerDefaults.V3First(Cpu, Compact);

    /// <summary>
    /// Version 3: SMW92, the receive's end timeout. <see cref="CharTimeoutMs"/> when set, else the character time
    /// rounded down plus 2 ms (the timer counts in whole ms, so it must outlast one character by more than 1 ms), and
    /// at least the cable's turnaround, since the reply cannot start before the receive ends (docs/protocol.md section 1.5).
    /// </summary>
    public int EffectiveEndTimeoutMs => CharTimeoutMs > 0 ? CharTimeoutMs : V3LinkOptions.DefaultEndTimeoutMs(BaudRate, Parity, DataBits);

    /// <summary>
    /// Version 3: the write mask as the handler applies it: Q, M and V only (protocol 3 never writes I or SM).
    /// </summary>
    public int EffectiveV3WriteMask => WriteMask & 0x1C;

    /// <summary>
    /// The PC/PPI cable's turnaround at this baud rate, rounded up to whole ms: 28 ms at 1200 baud, halving per doubling
    /// (docs/sources/s7200-facts.md section 7, unconfirmed: the remembered table; the larger figures are taken). The
    /// reply may not start earlier after the request's last character, so SMW92 is never shorter.
    /// </summary>
    public int TurnaroundMs => (int)Math.Ceiling(28.0 * 1200 / BaudRate);

    /// <summary>One character on the line in ms: start bit, data bits, parity bit if any, 1 stop bit.</summary>
    public double CharacterMs => 1000.0 * (2 + DataBits + (Parity == Parity.None ? 0 : 1)) / BaudRate;

    public int EffectiveFirstSubroutine => FirstSubroutine ?? HandlerDefaults.FirstSubroutine(Cpu);

    public int EffectiveFirstInterrupt => FirstInterrupt ?? HandlerDefaults.FirstInterrupt(Cpu);

    /// <summary>
    /// How many interrupt routines the handler takes from <see cref="EffectiveFirstInterrupt"/> on: protocol 3 two
    /// (receive complete, transmit complete), protocol 2 three (and its timed reply delay).
    /// </summary>
    public int InterruptRoutines => Protocol == 3 ? 2 : Handler.HandlerLayout.Interrupts;
}
