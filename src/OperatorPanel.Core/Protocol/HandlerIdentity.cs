using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Core.Protocol;

/// <summary>The fixed codes of the IDENTIFY reply (docs/protocol-v2.md, "01 IDENTIFY").</summary>
public static class HandlerIdentity
{
    /// <summary>Version 2: CRC frame check, REQCHECK in every reply, STOP, READ CHANGES (docs/protocol-v2.md).</summary>
    public const byte ProtocolVersion = 0x02;

    public const byte HandlerRevision = 0x01;

    /// <summary>
    /// MAX_READ_DATA: 116 = 16#74, the data a one-item READ may carry. A READ of N items carries at most
    /// <see cref="ProtocolLimits.MaxReadDataFor"/>(N) = floor((237 - 4N) / 2) bytes.
    /// </summary>
    public const byte MaxReadData = ProtocolLimits.MaxReadData;

    /// <summary>STATUS_FLAGS bit 0: SM0.7, the mode switch is at RUN.</summary>
    public const byte ModeSwitchRunFlag = 0x01;

    /// <summary>FEATURES bit 0: the handler was generated with STOP (command 07) enabled.</summary>
    public const byte StopFeature = 0x01;

    /// <summary>FEATURES bit 1: the handler has READ CHANGES copies (COPY_BYTES &gt; 0).</summary>
    public const byte CopiesFeature = 0x02;

    /// <summary>FEATURES bit 2: the handler answers 09 READ CHANGES OF LISTS (else 09 is error 05).</summary>
    public const byte ChangesOfListsFeature = 0x04;

    /// <summary>CPU_MODEL: 1 = 221, 2 = 222, 3 = 224, 4 = 224XP, 5 = 226.</summary>
    public static byte CpuModelCode(CpuModel model) => model switch
    {
        CpuModel.Cpu221 => 1,
        CpuModel.Cpu222 => 2,
        CpuModel.Cpu224 => 3,
        CpuModel.Cpu224XP => 4,
        CpuModel.Cpu226 => 5,
    };

    /// <summary>CPU_REVISION: 0 = Early, 1 = Current.</summary>
    public static byte CpuRevisionCode(CpuRevision revision) => revision == CpuRevision.Early ? (byte)0 : (byte)1;
}
