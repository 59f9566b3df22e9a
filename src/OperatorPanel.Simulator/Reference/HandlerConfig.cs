using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// What the handler is generated with: station, port, write mask (bit n = area code n writable; bit 1, I, never),
/// reply delay (1-255 ms, SMB34), the CPU and where its own V bytes start (by default where the generator puts them:
/// the end of V). Invalid settings are programming errors and throw.
/// </summary>
public sealed record HandlerConfig
{
    /// <summary>Q, M, V and SM writable (bits 2-5).</summary>
    public const byte DefaultWriteMask = 0x3C;

    /// <summary>
    /// The handler's own V bytes: the 256-byte buffer and 36 work bytes (docs/protocol.md "Work bytes"; the same
    /// figure as StlGen's HandlerLayout, which a StlGen test compares).
    /// </summary>
    public const int HandlerVBytes = 256 + 36;

    public HandlerConfig(Station station, CpuProfile cpu, int port = 0, byte writeMask = DefaultWriteMask, byte replyDelayMs = 5, int? bufferStart = null)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        ArgumentOutOfRangeException.ThrowIfNegative(port);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(port, cpu.CommunicationPorts);
        ArgumentOutOfRangeException.ThrowIfZero(replyDelayMs);
        if ((writeMask & ~DefaultWriteMask) != 0)
        {
            throw new ArgumentOutOfRangeException(nameof(writeMask), writeMask, "only bits 2-5 (Q, M, V, SM) may be set; I is never writable");
        }

        (Station, Cpu, Port, WriteMask, ReplyDelayMs) = (station, cpu, port, writeMask, replyDelayMs);
        var vBytes = cpu.TryGetArea(MemoryArea.V, out var v) ? v.ByteCount : 0;
        BufferStart = bufferStart ?? ((vBytes - HandlerVBytes) & ~1);
        ArgumentOutOfRangeException.ThrowIfNegative(BufferStart, nameof(bufferStart));
        ArgumentOutOfRangeException.ThrowIfGreaterThan(BufferStart + HandlerVBytes, vBytes, nameof(bufferStart));
    }

    /// <summary>V byte offset of the handler's buffer; its own bytes are BufferStart .. BufferStart + 291.</summary>
    public int BufferStart { get; }

    public Station Station { get; }

    public CpuProfile Cpu { get; }

    public int Port { get; }

    public byte WriteMask { get; }

    public byte ReplyDelayMs { get; }

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
