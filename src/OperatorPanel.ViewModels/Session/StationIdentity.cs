using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.ViewModels.Session;

/// <summary>What a station said about itself in its IDENTIFY reply (docs/protocol.md, "01 IDENTIFY").</summary>
/// <param name="Model">The CPU model the handler was generated for; null for a code this panel does not know.</param>
/// <param name="Revision">Early or current, as the handler was generated.</param>
/// <param name="ProtocolVersion">The frame protocol the handler speaks; this panel speaks version 3.</param>
/// <param name="HandlerRevision">The generator revision of the handler program.</param>
/// <param name="Smb6">SMB6, the CPU identifier register (CPU type in bits 4-7, seed 002 Table C-7).</param>
/// <param name="ModeSwitchRun">SM0.7: the mode switch is at RUN.</param>
/// <param name="LastScanMs">SMW22, last scan time in ms (seed 002 Table C-9).</param>
/// <param name="MinScanMs">SMW24, shortest scan since RUN.</param>
/// <param name="MaxScanMs">SMW26, longest scan since RUN.</param>
public sealed record StationIdentity(
    CpuModel? Model,
    CpuRevision Revision,
    byte ProtocolVersion,
    byte HandlerRevision,
    byte Smb6,
    bool ModeSwitchRun,
    ushort LastScanMs,
    ushort MinScanMs,
    ushort MaxScanMs)
{
    /// <summary>The protocol this panel speaks (docs/protocol.md).</summary>
    public const byte PanelProtocol = Core.Protocol.V3.Identity.ProtocolVersion;

    public bool ProtocolMatches => ProtocolVersion == PanelProtocol;

    /// <summary>The whole v3 IDENTIFY (the handler's shape: list, STOP, MAX_REQUEST, END_TIMEOUT_MS, V bytes); null for an older reply.</summary>
    public Core.Protocol.V3.Identity? V3 { get; init; }

    /// <summary>FEATURES bit 0: the handler was generated with 08 STOP (docs/protocol.md, "01 IDENTIFY").</summary>
    public bool StopEnabled { get; init; }

    public string CpuText => Model is { } model
        ? CpuModelNames.Format(model) + (Revision == CpuRevision.Early ? " (early)" : string.Empty)
        : "unknown CPU code";

    public static StationIdentity From(IdentifyResponse reply)
    {
        ArgumentNullException.ThrowIfNull(reply);
        CpuModel? model = Enum.GetValues<CpuModel>().Where(m => HandlerIdentity.CpuModelCode(m) == reply.CpuModelCode).Select(m => (CpuModel?)m).FirstOrDefault();
        var revision = reply.CpuRevisionCode == HandlerIdentity.CpuRevisionCode(CpuRevision.Early) ? CpuRevision.Early : CpuRevision.Current;
        return new StationIdentity(
            model, revision, reply.ProtocolVersion, reply.HandlerRevision, reply.Smb6, reply.ModeSwitchRun,
            reply.LastScanMs, reply.MinScanMs, reply.MaxScanMs)
        {
            StopEnabled = reply.StopEnabled,
            V3 = reply.V3Identity,
        };
    }

    /// <summary>True when the PLC's CPU is not the one the project's addresses were checked against.</summary>
    public bool Contradicts(CpuProfile projectCpu)
    {
        ArgumentNullException.ThrowIfNull(projectCpu);
        return Model != projectCpu.Model || Revision != projectCpu.Revision;
    }
}
