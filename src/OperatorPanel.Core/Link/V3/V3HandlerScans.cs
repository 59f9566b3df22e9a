using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Core.Link.V3;

/// <summary>
/// How many scans of the CPU a v3 handler takes from a request to the slice that ends its reply's check, per command:
/// the worst case of each row of <c>opanel generate --stats</c> for the full handler (CPU 224, the sample project, at
/// v3all 1e2dd0a), rounded up: IDENTIFY 7, READ of 16 bytes 8, WRITE of 16 bytes 10, WRITE BITS 6, DEFINE LIST of 32
/// items 84, READ LIST 45 (25 entries changed), READ LIST FULL 23. STOP has no row; it is timed as WRITE. The link
/// multiplies them by its allowance per scan (<see cref="LinkOptions.HandlerScanAllowance"/>) for the reply time-out.
/// When the handler changes, take the figures from its --stats table again.
/// </summary>
public static class V3HandlerScans
{
    public static int For(Command command) => command switch
    {
        Command.Identify => 7,
        Command.Read => 8,
        Command.Write or Command.Stop => 10,
        Command.WriteBits => 6,
        Command.DefineList => 84,
        Command.ReadList => 45,
        Command.ReadListFull => 23,
        _ => 10,
    };
}
