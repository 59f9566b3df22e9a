using System.Globalization;
using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// An IDENTIFY reply decoded for people (docs/protocol.md section 2, "01 IDENTIFY"); text and JSON share this shape.
/// The v3 fields (LIST_ITEMS, LIST_BYTES, MAX_REQUEST, END_TIMEOUT_MS, FEATURES, V_FIRST/V_BYTES) come from the v3
/// identity the link keeps with the reply.
/// </summary>
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
    string Handler,
    string Features,
    bool ListEnabled,
    int ListItems,
    int ListBytes,
    int MaxRequest,
    int EndTimeoutMs,
    int VFirst,
    int VBytes,
    int MaxReadData,
    bool StopEnabled,
    string? ExpectedCpu,
    string? CpuMismatch)
{
    public static IdentifyView From(LinkTarget target, IdentifyResponse r)
    {
        var model = IdentifyCheck.GeneratedFor(r);
        var revision = r.CpuRevisionCode == HandlerIdentity.CpuRevisionCode(CpuRevision.Early) ? CpuRevision.Early : CpuRevision.Current;
        var generatedFor = model is { } m2 ? $"{CpuModelNames.Format(m2)} ({revision})" : $"unknown CPU code {r.CpuModelCode}";
        var cpuId = (byte)(r.Smb6 & 0xF0);
        var smb6Models = CpuProfiles.All.Where(p => p.CpuIdCode == cpuId).Select(p => CpuModelNames.Format(p.Model)).Distinct().ToList();
        var smb6Means = smb6Models.Count == 0 ? "unknown CPU type" : string.Join(" or ", smb6Models);
        var areas = Enum.GetValues<ProtocolArea>().Where(a => (r.WriteMask & (1 << (int)a)) != 0).Select(a => a.ToString()).ToList();
        var v3 = r.V3Identity;
        var features = new[] { (v3?.HasList ?? false) ? "list" : null, r.StopEnabled ? "STOP" : null }.OfType<string>().ToList();
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
            v3 is null ? "unknown (not a v3 identity)" : v3.HasList ? "full" : "compact",
            Hex(r.Features) + (features.Count == 0 ? string.Empty : ": " + string.Join(", ", features)),
            v3?.HasList ?? false,
            v3?.ListItems ?? 0,
            v3?.ListBytes ?? 0,
            v3?.MaxRequestBytes ?? 0,
            r.ReplyDelayMs,
            r.VFirst,
            r.VBytes,
            r.MaxReadData,
            r.StopEnabled,
            target.Cpu?.DisplayName,
            target.Cpu is null ? null : IdentifyCheck.Mismatch(r, target.Cpu));
    }

    private static string Hex(byte value) => "16#" + value.ToString("X2", CultureInfo.InvariantCulture);

    public void WriteText(TextWriter o)
    {
        o.WriteLine($"station       {Station} on {Port}");
        o.WriteLine($"protocol      version {ProtocolVersion}, handler revision {HandlerRevision}, {Handler} handler, at most {MaxReadData} bytes per READ (MAX_DATA)");
        o.WriteLine($"generated for {GeneratedFor}");
        o.WriteLine($"SMB6          {Smb6}: {Smb6Means}");
        o.WriteLine($"mode switch   {ModeSwitch}");
        o.WriteLine($"scan          last {LastScanMs} ms, min {MinScanMs} ms, max {MaxScanMs} ms");
        o.WriteLine($"write mask    {WriteMask}: {(WritableAreas.Count == 0 ? "nothing writable" : string.Join(" ", WritableAreas))}");
        o.WriteLine($"FEATURES      {Features}");
        o.WriteLine(ListEnabled
            ? $"list          {ListItems} items, {ListBytes} bytes (LIST_ITEMS, LIST_BYTES): one READ LIST a refresh"
            : "list          none (compact handler): read with READs of at most 16 bytes");
        o.WriteLine($"requests      at most {MaxRequest} bytes (MAX_REQUEST)");
        o.WriteLine($"end time-out  {EndTimeoutMs} ms (END_TIMEOUT_MS: the receive ends this long after the last character; no reply starts sooner)");
        o.WriteLine($"handler V     VB{VFirst}-VB{VFirst + VBytes - 1} ({VBytes} bytes, V_FIRST/V_BYTES: never written by the panel)");
        o.WriteLine($"STOP          {(StopEnabled ? "in the handler (FEATURES bit 0): opanel stop can put it into STOP" : "not in the handler")}");
        if (ExpectedCpu is not null)
        {
            o.WriteLine(CpuMismatch is null ? $"cpu check     ok: matches {ExpectedCpu}" : $"cpu check     MISMATCH with {ExpectedCpu}: {CpuMismatch}");
        }
    }
}
