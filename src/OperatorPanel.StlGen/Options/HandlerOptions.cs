using OperatorPanel.Core.Cpu;
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

    /// <summary>The first of the handler's three interrupt routines; null = <see cref="HandlerDefaults.FirstInterrupt"/>.</summary>
    public int? FirstInterrupt { get; init; }

    public HandlerBlockNames Names { get; init; } = new();

    /// <summary>
    /// 0-255 V bytes after the work bytes for READ CHANGES copies (docs/protocol.md, "READ CHANGES"); 0 = none, every
    /// READ CHANGES then answers the whole list.
    /// </summary>
    public int CopyBytes { get; init; } = HandlerDefaults.CopyBytes;

    /// <summary>Whether the handler carries 07 STOP; off = no STOP code at all, CMD 07 gets error 05 like any unknown command.</summary>
    public bool AllowStop { get; init; }

    /// <summary>The settings a project fixes for one station: CPU, station address, baud, parity, data and stop bits, STOP.</summary>
    public static HandlerOptions For(ProjectStation station)
    {
        ArgumentNullException.ThrowIfNull(station);
        return new HandlerOptions
        {
            Cpu = station.Cpu,
            Station = station.Address.Address,
            BaudRate = station.Link.BaudRate,
            Parity = station.Link.Parity,
            DataBits = station.Link.DataBits,
            StopBits = station.Link.StopBits,
            AllowStop = station.AllowStop,
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

    public int EffectiveFirstSubroutine => FirstSubroutine ?? HandlerDefaults.FirstSubroutine(Cpu);

    public int EffectiveFirstInterrupt => FirstInterrupt ?? HandlerDefaults.FirstInterrupt(Cpu);
}
