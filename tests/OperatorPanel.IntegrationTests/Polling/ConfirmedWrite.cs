using System.Collections.Immutable;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.IntegrationTests.Polling;

/// <summary>
/// What a write over a real-time pty may end as and still be right: confirmed by its reply's read-back or, when a
/// stalled host missed the reply (CI saw it at load averages of 10 and more), confirmed by the read-back that settles a
/// lost reply. Both say the PLC holds the value and the write went out once; anything else fails the test.
/// </summary>
internal static class ConfirmedWrite
{
    public static ImmutableArray<byte> ReadBackOf(WriteOutcome outcome)
    {
        outcome.Should().Match<WriteOutcome>(o => o is WriteOutcome.Confirmed || o is WriteOutcome.ConfirmedByReadBack, "the write must be confirmed");
        return outcome switch
        {
            WriteOutcome.Confirmed confirmed => confirmed.ReadBack,
            WriteOutcome.ConfirmedByReadBack settled => settled.ReadBack,
            _ => [],
        };
    }
}
