using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Writes;
using OperatorPanel.ViewModels.Session;

namespace OperatorPanel.ViewModels.Tests.Session;

/// <summary>What the operator reads after a write, on the row and in the status line, lost replies included.</summary>
public sealed class WriteMessagesTests
{
    private static readonly PlcAddress Vw10 = PlcAddress.Parse("VW10");

    [Fact]
    public void StatusText_ConfirmedByReadBack_SaysWrittenAndThatTheReplyWasLostWithNoRowError()
    {
        var outcome = new WriteOutcome.ConfirmedByReadBack([0x00, 0x08], "no reply within 120 ms");

        WriteMessages.Problem(Vw10, DisplayFormat.Unsigned, outcome).Should().BeNull();
        WriteMessages.StatusText("Speed", Vw10, DisplayFormat.Unsigned, "8", outcome)
            .Should().Be("VW10 (Speed): 8 written, confirmed by reading back (the reply was lost: no reply within 120 ms)");
    }

    [Fact]
    public void Problem_NotApplied_NamesTheOldValueAndSaysToWriteAgain()
    {
        var outcome = new WriteOutcome.NotApplied([0x00, 0x07], "no reply within 120 ms");

        WriteMessages.Problem(Vw10, DisplayFormat.Unsigned, outcome).Should().Be(
            "not applied: the reply was lost (no reply within 120 ms) and the PLC still holds 7; write it again if it is still wanted");
    }

    [Fact]
    public void StatusText_Unknown_SaysNotConfirmedAndToCheckBeforeWritingAgain()
    {
        var outcome = new WriteOutcome.Unknown(default, "no reply within 120 ms", "the read-back failed too (NoAnswer: no answer)");

        WriteMessages.StatusText("Speed", Vw10, DisplayFormat.Unsigned, "8", outcome).Should().Be(
            "VW10 (Speed): write of 8 not confirmed: unknown whether written: no reply within 120 ms; the read-back failed too (NoAnswer: no answer); "
            + "the PLC may or may not have applied it: check the value on the PLC before writing again");
    }
}
