using System.Globalization;
using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Ppi;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// What PPI tells about a CPU (<see cref="PpiIdentity"/>: SMB6, SM0.7, SMW22-SMW26; docs/ppi.md section 9), for people;
/// text and JSON share this shape. RUN or STOP is not among it: no source gives a PPI query for the S7-200's mode, so
/// it is shown as unknown, never guessed.
/// </summary>
internal sealed record PpiIdentifyView(
    int Station,
    string Port,
    string Link,
    string Smb6,
    string Smb6Means,
    string ModeSwitch,
    string Mode,
    int LastScanMs,
    int MinScanMs,
    int MaxScanMs,
    string? ExpectedCpu,
    string? CpuMismatch)
{
    public const string ModeUnknown = "unknown over PPI (no published PPI query gives RUN or STOP; the switch position is SM0.7)";

    public static PpiIdentifyView From(LinkTarget target, PpiIdentity identity)
    {
        ArgumentNullException.ThrowIfNull(target);
        ArgumentNullException.ThrowIfNull(identity);
        return new PpiIdentifyView(
            target.Station.Address,
            target.Serial.PortName,
            $"PPI {target.Serial.LineText}, no handler",
            Hex(identity.Smb6),
            Means(identity.Smb6),
            identity.SwitchAtRun ? "RUN" : "TERM",
            ModeUnknown,
            identity.LastScanMs,
            identity.MinScanMs,
            identity.MaxScanMs,
            target.Cpu?.DisplayName,
            target.Cpu is null ? null : Mismatch(target.Cpu, identity.Smb6));
    }

    /// <summary>The one line watch shows for a PPI station where a Freeport station shows its handler check.</summary>
    public static string Check(CpuProfile expected, PpiIdentifyOutcome outcome)
    {
        ArgumentNullException.ThrowIfNull(expected);
        ArgumentNullException.ThrowIfNull(outcome);
        if (outcome.Identity is not { } identity)
        {
            return $"no handler (PPI); not identified: {outcome.Error}";
        }

        var switchText = identity.SwitchAtRun ? "RUN" : "TERM";
        return Mismatch(expected, identity.Smb6) is { } mismatch
            ? $"no handler (PPI); MISMATCH with {expected.DisplayName}: {mismatch}"
            : $"no handler (PPI); ok: SMB6 {Hex(identity.Smb6)} ({Means(identity.Smb6)}), mode switch {switchText}, RUN/STOP unknown over PPI";
    }

    public void WriteText(TextWriter o)
    {
        ArgumentNullException.ThrowIfNull(o);
        o.WriteLine($"station       {Station} on {Port}");
        o.WriteLine($"link          {Link}");
        o.WriteLine($"SMB6          {Smb6}: {Smb6Means}");
        o.WriteLine($"mode switch   {ModeSwitch}");
        o.WriteLine($"mode          {Mode}");
        o.WriteLine($"scan          last {LastScanMs} ms, min {MinScanMs} ms, max {MaxScanMs} ms");
        if (ExpectedCpu is not null)
        {
            o.WriteLine(CpuMismatch is null ? $"cpu check     ok: matches {ExpectedCpu}" : $"cpu check     MISMATCH with {ExpectedCpu}: {CpuMismatch}");
        }
    }

    /// <summary>SMB6 bits 4-7 by code only: CPU 224 and 224XP share 16#20 (docs/cpu-profiles.md).</summary>
    private static string? Mismatch(CpuProfile expected, byte smb6)
    {
        var cpuId = (byte)(smb6 & 0xF0);
        return cpuId == expected.CpuIdCode ? null : $"the PLC reports SMB6 {Hex(cpuId)} ({Means(smb6)}), {expected.Name} has {Hex(expected.CpuIdCode)}";
    }

    private static string Means(byte smb6)
    {
        var models = CpuProfiles.All.Where(p => p.CpuIdCode == (smb6 & 0xF0)).Select(p => CpuModelNames.Format(p.Model)).Distinct().ToList();
        return models.Count == 0 ? "unknown CPU type" : string.Join(" or ", models);
    }

    private static string Hex(byte value) => "16#" + value.ToString("X2", CultureInfo.InvariantCulture);
}
