using System.Globalization;
using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Cli.Commands;

/// <summary>An IDENTIFY reply decoded for people (docs/protocol.md, "01 IDENTIFY"); text and JSON share this shape.</summary>
internal sealed record IdentifyView(
    int Station,
    string Port,
    int ProtocolVersion,
    int HandlerRevision,
    string GeneratedFor,
    string Smb6,
    string Smb6Means,
    string ModeSwitch,
    int LastScanMs,
    int MinScanMs,
    int MaxScanMs,
    string WriteMask,
    IReadOnlyList<string> WritableAreas,
    int ReplyDelayMs,
    int MaxReadData,
    bool StopEnabled,
    string? ExpectedCpu,
    string? CpuMismatch)
{
    public static IdentifyView From(LinkTarget target, IdentifyResponse r)
    {
        var model = Enum.GetValues<CpuModel>().Where(m => HandlerIdentity.CpuModelCode(m) == r.CpuModelCode).Select(m => (CpuModel?)m).FirstOrDefault();
        var revision = r.CpuRevisionCode == HandlerIdentity.CpuRevisionCode(CpuRevision.Early) ? CpuRevision.Early : CpuRevision.Current;
        var generatedFor = model is { } m2 ? $"{CpuModelNames.Format(m2)} ({revision})" : $"unknown CPU code {r.CpuModelCode}";
        var cpuId = (byte)(r.Smb6 & 0xF0);
        var smb6Models = CpuProfiles.All.Where(p => p.CpuIdCode == cpuId).Select(p => CpuModelNames.Format(p.Model)).Distinct().ToList();
        var smb6Means = smb6Models.Count == 0 ? "unknown CPU type" : string.Join(" or ", smb6Models);
        var areas = Enum.GetValues<ProtocolArea>().Where(a => (r.WriteMask & (1 << (int)a)) != 0).Select(a => a.ToString()).ToList();
        return new IdentifyView(
            target.Station.Address,
            target.Serial.PortName,
            r.ProtocolVersion,
            r.HandlerRevision,
            generatedFor,
            Hex(r.Smb6),
            smb6Means,
            r.ModeSwitchRun ? "RUN" : "TERM",
            r.LastScanMs,
            r.MinScanMs,
            r.MaxScanMs,
            Hex(r.WriteMask),
            areas,
            r.ReplyDelayMs,
            r.MaxReadData,
            r.StopEnabled,
            target.Cpu?.DisplayName,
            target.Cpu is null ? null : Mismatch(target.Cpu, model, cpuId, smb6Means));
    }

    /// <summary>
    /// CPU 224 and 224XP share SMB6 16#20 (docs/cpu-profiles.md), so SMB6 is compared by code only; the handler's own CPU
    /// code names the exact model it was generated for.
    /// </summary>
    private static string? Mismatch(CpuProfile expected, CpuModel? generatedFor, byte cpuId, string smb6Means)
    {
        var problems = new List<string>();
        if (cpuId != expected.CpuIdCode)
        {
            problems.Add($"the PLC reports SMB6 {Hex(cpuId)} ({smb6Means}), {expected.Name} has {Hex(expected.CpuIdCode)}");
        }

        if (generatedFor != expected.Model)
        {
            var name = generatedFor is { } m ? CpuModelNames.Format(m) : "an unknown CPU";
            problems.Add($"the handler was generated for {name}, not {expected.Name}: regenerate it");
        }

        return problems.Count == 0 ? null : string.Join("; ", problems);
    }

    private static string Hex(byte value) => "16#" + value.ToString("X2", CultureInfo.InvariantCulture);

    public void WriteText(TextWriter o)
    {
        o.WriteLine($"station       {Station} on {Port}");
        o.WriteLine($"protocol      version {ProtocolVersion}, handler revision {HandlerRevision}, at most {MaxReadData} bytes per READ (2 fewer per further item)");
        o.WriteLine($"generated for {GeneratedFor}");
        o.WriteLine($"SMB6          {Smb6}: {Smb6Means}");
        o.WriteLine($"mode switch   {ModeSwitch}");
        o.WriteLine($"scan          last {LastScanMs} ms, min {MinScanMs} ms, max {MaxScanMs} ms");
        o.WriteLine($"write mask    {WriteMask}: {(WritableAreas.Count == 0 ? "nothing writable" : string.Join(" ", WritableAreas))}");
        o.WriteLine($"reply delay   {ReplyDelayMs} ms");
        o.WriteLine($"STOP          {(StopEnabled ? "in the handler (FEATURES bit 0): opanel stop can put it into STOP" : "not in the handler")}");
        if (ExpectedCpu is not null)
        {
            o.WriteLine(CpuMismatch is null ? $"cpu check     ok: matches {ExpectedCpu}" : $"cpu check     MISMATCH with {ExpectedCpu}: {CpuMismatch}");
        }
    }
}
