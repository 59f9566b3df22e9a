using OperatorPanel.Cli.Commands;
using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Transport;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.Cli.Tests.Commands;

/// <summary>How <c>opanel write</c> prints a write whose reply was lost, and the exit code a script sees.</summary>
public sealed class WriteResultViewTests
{
    private static readonly WriteItem Vw10 = Item("VW10=8");

    public static TheoryData<WriteOutcome, string, int> LostReplies => new()
    {
        {
            new WriteOutcome.ConfirmedByReadBack([0x00, 0x08], "no reply within 120 ms"),
            "VW10     ? -> 8  confirmed (reply lost, read back): no reply within 120 ms", 0
        },
        {
            new WriteOutcome.NotApplied([0x00, 0x07], "no reply within 120 ms"),
            "VW10     ? -> 8  not applied: the reply was lost (no reply within 120 ms) and the PLC still holds 7; write it again if it is still wanted", 2
        },
        {
            new WriteOutcome.Unknown(default, "no reply within 120 ms", "the read-back failed too (NoAnswer: no answer)"),
            "VW10     ? -> 8  unknown: no reply within 120 ms; the read-back failed too (NoAnswer: no answer); "
            + "the PLC may or may not have applied it: check the value on the PLC before writing again", 3
        },
        {
            new WriteOutcome.Failed("PortUnavailable: COM9 is gone; nothing was sent", WriteFailureKind.LinkFailure),
            "VW10     ? -> 8  failed: PortUnavailable: COM9 is gone; nothing was sent", 2
        },
    };

    [Theory]
    [MemberData(nameof(LostReplies))]
    public void WriteText_LostReplyOutcomes_PrintTheVerdictTheNextStepAndTheirExitCode(WriteOutcome outcome, string line, int exitCode)
    {
        var view = WriteResultView.From(Vw10, null, outcome);
        using var text = new StringWriter();

        view.WriteText(text);

        text.ToString().TrimEnd().Should().Be(line);
        view.ExitCode.Should().Be(exitCode);
    }

    private static WriteItem Item(string text)
    {
        var target = new LinkTarget(new Station(2), new SerialSettings { PortName = "COM9" }, null, Demo: false, TimeSpan.FromMilliseconds(100));
        WriteItem.TryParse(text, target, out var item, out var error).Should().BeTrue(error);
        return item!;
    }
}
