using OperatorPanel.Cli.Commands;
using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Stop;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Cli.Tests.Commands;

/// <summary>What <c>opanel stop</c> prints for each outcome, lost replies included, and the exit code a script sees.</summary>
public sealed class StopResultViewTests
{
    private static readonly Station Two = new(2);

    public static TheoryData<StopOutcome, string, string, int> Outcomes => new()
    {
        { new StopOutcome.Stopped(Two), "stopped", "station 2 stopped: the port speaks PPI until someone sets RUN", 0 },
        { new StopOutcome.StoppedReplyLost(Two, "no reply within 120 ms"), "stoppedReplyLost", "station 2 stopped (reply lost, station silent): no reply within 120 ms", 0 },
        { new StopOutcome.NotExecuted(Two), "notExecuted", "station 2 acknowledged STOP but still answers in Freeport: the STOP was not executed", 2 },
        {
            new StopOutcome.NotStopped(Two, "no reply within 120 ms"), "notStopped",
            "station 2 not stopped: the reply to STOP was lost (no reply within 120 ms) and the station still answers; send STOP again if still wanted", 2
        },
        { new StopOutcome.NotSent(Two, "COM9 is gone"), "notSent", "station 2: STOP not sent: COM9 is gone", 2 },
        { new StopOutcome.Refused(Two, "86: bad parameter"), "refused", "station 2 refused STOP: 86: bad parameter", 1 },
        {
            new StopOutcome.Unknown(Two, "no reply within 120 ms", "COM9 is gone"), "unknown",
            "station 2: unknown whether stopped: the reply to STOP was lost (no reply within 120 ms) and the check failed too (COM9 is gone); "
            + "look at the CPU's RUN/STOP LED before sending STOP again", 3
        },
    };

    [Theory]
    [MemberData(nameof(Outcomes))]
    public void From_EachOutcome_GivesItsNameSentenceAndExitCode(StopOutcome outcome, string name, string message, int exitCode)
    {
        var view = StopResultView.From(Target, outcome);

        view.Should().Be(new StopResultView(2, "COM9", name, message, exitCode));
    }

    [Fact]
    public void From_HandlerWithoutStop_IsBadInputNamingTheProjectSetting()
    {
        var view = StopResultView.From(Target, new StopOutcome.NotInHandler(Two));

        view.ExitCode.Should().Be(1);
        view.Outcome.Should().Be("notInHandler");
        view.Message.Should().Contain("\"allowStop\": true").And.Contain("--allow-stop").And.Contain("nothing sent");
    }

    private static LinkTarget Target => new(Two, new SerialSettings { PortName = "COM9" }, null, Demo: false, TimeSpan.FromMilliseconds(100));
}
