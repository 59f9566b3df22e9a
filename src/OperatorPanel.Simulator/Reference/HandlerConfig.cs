using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// What the handler is generated with: its protocol (<see cref="Protocol"/>: 3, what the panel speaks, or 2), station,
/// port, write mask (bit n = area code n writable; bit 1, I, never), the CPU, whether STOP is in it, and for the STL
/// model the receive timeout and block numbers. Protocol 3 adds the compact shape, END_TIMEOUT_MS (the receive
/// timeout, <see cref="CharTimeoutMs"/>; 0 = the line's default) and V_FIRST (<see cref="V3First"/>); protocol 2 the
/// reply delay (1-255 ms, SMB34), the buffer start and the READ CHANGES copies (COPY_BYTES). A v3 station is
/// simulated by Reference/V3's model from <see cref="V3SetupFor"/>.
/// Invalid settings are programming errors and throw.
/// </summary>
public sealed record HandlerConfig
{
    /// <summary>Q, M, V and SM writable (bits 2-5).</summary>
    public const byte DefaultWriteMask = 0x3C;

    public HandlerConfig(
        Station station,
        CpuProfile cpu,
        int port = 0,
        byte writeMask = DefaultWriteMask,
        byte replyDelayMs = 5,
        int? bufferStart = null,
        bool allowStop = false,
        int copyBytes = HandlerMemory.DefaultCopyBytes,
        int charTimeoutMs = 0,
        int? firstSubroutine = null,
        int? firstInterrupt = null)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        ArgumentOutOfRangeException.ThrowIfNegative(copyBytes);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(copyBytes, HandlerMemory.MaxCopyBytes);
        ArgumentOutOfRangeException.ThrowIfNegative(port);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(port, cpu.CommunicationPorts);
        ArgumentOutOfRangeException.ThrowIfZero(replyDelayMs);
        if ((writeMask & ~DefaultWriteMask) != 0)
        {
            throw new ArgumentOutOfRangeException(nameof(writeMask), writeMask, "only bits 2-5 (Q, M, V, SM) may be set; I is never writable");
        }

        ArgumentOutOfRangeException.ThrowIfNegative(charTimeoutMs);
        (Station, Cpu, Port, WriteMask, ReplyDelayMs, AllowStop, CopyBytes) = (station, cpu, port, writeMask, replyDelayMs, allowStop, copyBytes);
        (CharTimeoutMs, FirstSubroutine, FirstInterrupt) = (charTimeoutMs, firstSubroutine, firstInterrupt);
        var vBytes = cpu.TryGetArea(MemoryArea.V, out var v) ? v.ByteCount : 0;
        BufferStart = bufferStart ?? ((vBytes - HandlerVBytes) & ~1);
        ArgumentOutOfRangeException.ThrowIfNegative(BufferStart, nameof(bufferStart));
        ArgumentOutOfRangeException.ThrowIfGreaterThan(BufferStart + HandlerVBytes, vBytes, nameof(bufferStart));
    }

    /// <summary>3 (binary frames: what the panel speaks; default) or 2 (hex frames: the panel tells it to regenerate).</summary>
    public int Protocol { get; init; } = 3;

    /// <summary>Protocol 3: the compact handler (IDENTIFY, READ, WRITE, WRITE BITS; no list, no STOP).</summary>
    public bool Compact { get; init; }

    /// <summary>Protocol 3: V_FIRST as given (--buffer); null = the top of V for the shape.</summary>
    public int? V3First { get; init; }

    /// <summary>
    /// The protocol 3 setup of this station on <paramref name="serial"/>'s line: compact or full, Q/M/V of the write
    /// mask, END_TIMEOUT_MS as given or the line's default (as the generator takes it), STOP unless compact.
    /// </summary>
    public V3.HandlerSetup V3SetupFor(Core.Transport.SerialSettings serial)
    {
        ArgumentNullException.ThrowIfNull(serial);
        var end = CharTimeoutMs > 0 ? CharTimeoutMs : Core.Link.V3.V3LinkOptions.DefaultEndTimeoutMs(serial);
        return new V3.HandlerSetup(
            Station, Cpu, Compact ? Core.Protocol.V3.HandlerShape.Compact : Core.Protocol.V3.HandlerShape.Full, Port,
            (byte)(WriteMask & V3.HandlerSetup.DefaultWriteMask), (byte)end, AllowStop && !Compact, V3First);
    }

    /// <summary>Protocol 2: V byte offset of the handler's buffer: V_FIRST in IDENTIFY.</summary>
    public int BufferStart { get; }

    /// <summary>
    /// The handler's own V bytes, V_BYTES in IDENTIFY: the 256-byte buffer, the work bytes and the copies
    /// (<see cref="HandlerMemory"/>, the figures StlGen's HandlerLayout uses too).
    /// </summary>
    public int HandlerVBytes => HandlerMemory.VBytes(CopyBytes);

    /// <summary>STOP (07) is in the handler (HandlerOptions.AllowStop); without it 07 is an unknown command (05).</summary>
    public bool AllowStop { get; }

    /// <summary>COPY_BYTES: V bytes for the READ CHANGES copies of the lists, 0-255; 0 = every READ CHANGES answers FULL.</summary>
    public int CopyBytes { get; }

    public Station Station { get; }

    public CpuProfile Cpu { get; }

    public int Port { get; }

    public byte WriteMask { get; }

    public byte ReplyDelayMs { get; }

    /// <summary>
    /// The receive inter-character timeout in ms (0 = off), the subroutine and first interrupt routine numbers (null =
    /// the generator's defaults): what the STL model's handler is generated with; the reference model has no receive
    /// timer and no blocks, so it ignores them.
    /// </summary>
    public int CharTimeoutMs { get; }

    public int? FirstSubroutine { get; }

    public int? FirstInterrupt { get; }

    public bool MayWrite(ProtocolArea area) => (WriteMask & (1 << (int)area)) != 0;

    /// <summary>A V byte of the handler's buffer or work bytes: refused to the panel (error 03).</summary>
    public bool IsHandlerVByte(int offset) => offset >= BufferStart && offset < BufferStart + HandlerVBytes;

    /// <summary>
    /// SM bytes refused to the panel: SMB0-SMB29 (system status), SMB34 (timed interrupt 0, the reply delay) and the
    /// port's own SMB30/SMB86-SMB94 (port 0) or SMB130/SMB186-SMB194 (port 1) (seed 002 Table C-16; spec, error 03).
    /// </summary>
    public bool IsProtectedSmByte(int offset)
    {
        var portBase = Port == 0 ? 0 : 100;
        return offset < Cpu.ReadOnlySmBytes
            || offset == 34
            || offset == portBase + 30
            || (offset >= portBase + 86 && offset <= portBase + 94);
    }
}
