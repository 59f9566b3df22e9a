using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Simulator.Reference.V3;

/// <summary>
/// What a v3 handler is generated with (docs/protocol.md section 6): station, port, write mask (bit n = area code n;
/// only Q, M and V: I and SM are never written), the receive's end timeout (SMW92, which also holds the reply back for
/// the converter's turnaround), full or compact shape, STOP, and where its V bytes start (by default the top of V).
/// Invalid settings are programming errors and throw.
/// </summary>
public sealed record HandlerSetup
{
    /// <summary>Q, M and V writable (bits 2-4).</summary>
    public const byte DefaultWriteMask = 0x1C;

    /// <summary>
    /// END_TIMEOUT_MS a generated handler has at 9600 8N1 by default (docs/protocol.md section 1.5: the cable's 4 ms
    /// turnaround over one character + 2 ms), so the reference answers IDENTIFY like one.
    /// </summary>
    public const byte DefaultEndTimeoutMs = 4;

    public HandlerSetup(
        Station station,
        CpuProfile cpu,
        HandlerShape? shape = null,
        int port = 0,
        byte writeMask = DefaultWriteMask,
        byte endTimeoutMs = DefaultEndTimeoutMs,
        bool allowStop = false,
        int? vFirst = null)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        ArgumentOutOfRangeException.ThrowIfNegative(port);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(port, cpu.CommunicationPorts);
        ArgumentOutOfRangeException.ThrowIfZero(endTimeoutMs);
        if ((writeMask & ~DefaultWriteMask) != 0)
        {
            throw new ArgumentOutOfRangeException(nameof(writeMask), writeMask, "only bits 2-4 (Q, M, V) may be set; I and SM are never written");
        }

        Shape = shape ?? HandlerShape.Full;
        (Station, Cpu, Port, WriteMask, EndTimeoutMs, AllowStop) = (station, cpu, port, writeMask, endTimeoutMs, allowStop);
        var vBytes = cpu.TryGetArea(MemoryArea.V, out var v) ? v.ByteCount : 0;
        VFirst = vFirst ?? Shape.DefaultVFirst(vBytes);
        ArgumentOutOfRangeException.ThrowIfNegative(VFirst, nameof(vFirst));
        ArgumentOutOfRangeException.ThrowIfGreaterThan(VFirst + Shape.VBytes, vBytes, nameof(vFirst));
    }

    public Station Station { get; }

    public CpuProfile Cpu { get; }

    public HandlerShape Shape { get; }

    public int Port { get; }

    public byte WriteMask { get; }

    /// <summary>SMW92: the receive ends this many ms after the last character (END_TIMEOUT_MS in IDENTIFY); no reply starts earlier.</summary>
    public byte EndTimeoutMs { get; }

    /// <summary>08 STOP is in the handler; without it 08 is an unknown command (85).</summary>
    public bool AllowStop { get; }

    /// <summary>V_FIRST: the first of the handler's V bytes.</summary>
    public int VFirst { get; }

    public bool MayWrite(ProtocolArea area) => (WriteMask & (1 << (int)area)) != 0;

    public bool IsHandlerVByte(int offset) => offset >= VFirst && offset < VFirst + Shape.VBytes;

    /// <summary>The IDENTIFY bytes 0-15 this setup fixes (bytes 16-23 come from the CPU at the moment of the reply).</summary>
    public Identity IdentityWith(byte smb6, byte statusFlags, ushort last, ushort min, ushort max)
    {
        var (model, revision) = Identity.CodesOf(Cpu);
        var features = (byte)((AllowStop ? Identity.StopFeature : 0) | (Shape.HasList ? Identity.ListFeature : 0));
        return new Identity(
            1, model, revision, WriteMask, features, EndTimeoutMs, (byte)Port, (byte)Shape.RequestBytes, (byte)HandlerShape.MaxData,
            (byte)Shape.ListItems, (byte)Shape.ListBytes, (ushort)VFirst, (ushort)Shape.VBytes, smb6, statusFlags, last, min, max);
    }
}
