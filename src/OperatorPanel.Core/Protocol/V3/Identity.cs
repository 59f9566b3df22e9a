using System.Buffers.Binary;
using System.Collections.Immutable;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Core.Protocol.V3;

/// <summary>
/// IDENTIFY's reply payload, 24 bytes (docs/protocol.md section 2, 01 IDENTIFY): what the handler was generated with
/// (bytes 0-15, fixed) and what the CPU reports now (bytes 16-23).
/// </summary>
public sealed record Identity(
    byte HandlerRevision,
    byte CpuModelCode,
    byte CpuRevisionCode,
    byte WriteMask,
    byte Features,
    byte EndTimeoutMs,
    byte Port,
    byte MaxRequestBytes,
    byte MaxData,
    byte ListItems,
    byte ListBytes,
    ushort VFirst,
    ushort VBytes,
    byte Smb6,
    byte StatusFlags,
    ushort LastScanMs,
    ushort MinScanMs,
    ushort MaxScanMs)
{
    public const byte ProtocolVersion = 3;
    public const int PayloadBytes = 24;

    /// <summary>FEATURES bit 0: 08 STOP is in the handler.</summary>
    public const byte StopFeature = 0x01;

    /// <summary>FEATURES bit 1: the list commands 05, 06 and 07 are in the handler (the full handler; the compact one has none).</summary>
    public const byte ListFeature = 0x02;

    /// <summary>STATUS_FLAGS bit 0: SM0.7, the mode switch at RUN. Bits 1-7 are always 0.</summary>
    public const byte ModeSwitchRunFlag = 0x01;

    /// <summary>The 16 bytes a handler's generation fixes, in payload order (bytes 0-15).</summary>
    public ImmutableArray<byte> FixedBytes =>
    [
        ProtocolVersion, HandlerRevision, CpuModelCode, CpuRevisionCode, WriteMask, Features, EndTimeoutMs, Port,
        MaxRequestBytes, MaxData, ListItems, ListBytes, (byte)(VFirst >> 8), (byte)VFirst, (byte)(VBytes >> 8), (byte)VBytes,
    ];

    /// <summary>The whole payload, bytes 0-23.</summary>
    public ImmutableArray<byte> ToPayload() =>
    [
        .. FixedBytes, Smb6, StatusFlags, (byte)(LastScanMs >> 8), (byte)LastScanMs, (byte)(MinScanMs >> 8), (byte)MinScanMs,
        (byte)(MaxScanMs >> 8), (byte)MaxScanMs,
    ];

    public bool HasStop => (Features & StopFeature) != 0;

    public bool HasList => (Features & ListFeature) != 0;

    /// <summary>The bytes of <paramref name="area"/> on the CPU this handler says it was generated for; 0 when CPU_MODEL is unknown.</summary>
    public int AreaBytes(ProtocolArea area)
    {
        var model = Enum.GetValues<CpuModel>().Where(m => HandlerIdentity.CpuModelCode(m) == CpuModelCode).Select(m => (CpuModel?)m).FirstOrDefault();
        var revision = CpuRevisionCode == HandlerIdentity.CpuRevisionCode(CpuRevision.Early) ? CpuRevision.Early : CpuRevision.Current;
        return model is { } known && CpuProfiles.TryFor(known, revision, out var profile) ? ListPlan.AreaBytesOf(profile)(area) : 0;
    }

    /// <summary>CPU_MODEL and CPU_REVISION of <paramref name="cpu"/>: 1 = 221 .. 5 = 226; 0 = Early, 1 = Current.</summary>
    public static (byte Model, byte Revision) CodesOf(CpuProfile cpu)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        return (HandlerIdentity.CpuModelCode(cpu.Model), HandlerIdentity.CpuRevisionCode(cpu.Revision));
    }

    /// <summary>Reads an IDENTIFY payload; false when it is not 24 bytes or PROTOCOL_VERSION is not 3.</summary>
    public static bool TryRead(ReadOnlySpan<byte> p, out Identity identity)
    {
        identity = null!;
        if (p.Length != PayloadBytes || p[0] != ProtocolVersion)
        {
            return false;
        }

        identity = new Identity(
            p[1], p[2], p[3], p[4], p[5], p[6], p[7], p[8], p[9], p[10], p[11],
            BinaryPrimitives.ReadUInt16BigEndian(p[12..]), BinaryPrimitives.ReadUInt16BigEndian(p[14..]), p[16], p[17],
            BinaryPrimitives.ReadUInt16BigEndian(p[18..]), BinaryPrimitives.ReadUInt16BigEndian(p[20..]), BinaryPrimitives.ReadUInt16BigEndian(p[22..]));
        return true;
    }
}
