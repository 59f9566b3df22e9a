using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Core.Link.V3;

/// <summary>
/// How many scans of the CPU a v3 handler takes from a request to the slice that ends its reply's check, per command:
/// the worst case of each row of <c>opanel generate --stats</c> for the full handler (CPU 224, the sample project, on
/// 2026-11-28 after the slot-window list: IDENTIFY 7, READ of 16 bytes 8, WRITE of 16 bytes 11, WRITE BITS 6 (7 before
/// the last phase reordering), DEFINE LIST of 32 items 84, READ LIST 46 (copy first), READ LIST FULL 24), plus one or two
/// scans for where in its phase order a request lands. STOP has no row; it is timed as WRITE. The link multiplies
/// them by its allowance per scan (<see cref="LinkOptions.HandlerScanAllowance"/>) for the reply time-out.
/// <c>V3HandlerScansTests</c> (StlGen) measures the generated handler on CPU 221, 224 and 226 and fails when a request
/// needs more than these: take the figures from --stats again then.
/// </summary>
public static class V3HandlerScans
{
    public static int For(Command command) => command switch
    {
        Command.Identify => 8,
        Command.Read => 9,
        Command.Write or Command.Stop => 12,
        Command.WriteBits => 8,
        Command.DefineList => 86,
        Command.ReadList => 48,
        Command.ReadListFull => 26,
        _ => 12,
    };
}
