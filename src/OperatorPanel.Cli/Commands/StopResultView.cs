using System.Text.Json;
using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Stop;

namespace OperatorPanel.Cli.Commands;

/// <summary>One STOP as <c>opanel stop</c> prints it (text and JSON share this shape).</summary>
/// <param name="Station">The station address.</param>
/// <param name="Port">The port it was sent on.</param>
/// <param name="Outcome">stopped, stoppedReplyLost, notExecuted, notStopped, notSent, notInHandler, refused or unknown.</param>
/// <param name="Message">The sentence for the operator, with the next step.</param>
/// <param name="ExitCode">What a script sees (the verb's help lists them).</param>
internal sealed record StopResultView(int Station, string Port, string Outcome, string Message, [property: System.Text.Json.Serialization.JsonIgnore] int ExitCode)
{
    public static StopResultView From(LinkTarget target, StopOutcome outcome)
    {
        ArgumentNullException.ThrowIfNull(target);
        ArgumentNullException.ThrowIfNull(outcome);
        var exitCode = outcome.Verdict switch
        {
            StopVerdict.Stopped or StopVerdict.StoppedReplyLost => ExitCodes.Ok,
            StopVerdict.NotExecuted or StopVerdict.NotStopped or StopVerdict.NotSent => ExitCodes.LinkFailure,
            StopVerdict.NotInHandler or StopVerdict.Refused or StopVerdict.WrongCpu => ExitCodes.BadInput,
            StopVerdict.Unknown => ExitCodes.WriteUnknown,
        };
        var name = JsonNamingPolicy.CamelCase.ConvertName(outcome.Verdict.ToString());
        return new StopResultView(target.Station.Address, target.Serial.PortName, name, outcome.Text, exitCode);
    }
}
