using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Stop;

/// <summary>
/// What became of a remote STOP (<see cref="RemoteStop"/>). A STOP is confirmed only by the station falling silent
/// afterwards: in STOP the CPU's port speaks PPI and answers no Freeport frame (docs/protocol-v2.md, "TERM and STOP").
/// </summary>
public abstract record StopOutcome
{
    private StopOutcome()
    {
    }

    public abstract Station Station { get; init; }

    /// <summary>One sentence for the operator, naming the station, with the next step where there is one.</summary>
    public abstract string Text { get; }

    public abstract StopVerdict Verdict { get; }

    /// <summary>The station is in STOP for certain or by the best evidence there is (silent after STOP).</summary>
    public bool IsStopped => Verdict is StopVerdict.Stopped or StopVerdict.StoppedReplyLost;

    /// <summary>STATUS 00 came, and the following IDENTIFY got no answer.</summary>
    public sealed record Stopped(Station Station) : StopOutcome
    {
        public override StopVerdict Verdict => StopVerdict.Stopped;

        public override string Text => $"{Station} stopped: the port speaks PPI until someone sets RUN";
    }

    /// <summary>The reply to STOP was lost, and the following IDENTIFY got no answer.</summary>
    public sealed record StoppedReplyLost(Station Station, string Cause) : StopOutcome
    {
        public override StopVerdict Verdict => StopVerdict.StoppedReplyLost;

        public override string Text => $"{Station} stopped (reply lost, station silent): {Cause}";
    }

    /// <summary>STATUS 00 came, yet the station still answers IDENTIFY in Freeport.</summary>
    public sealed record NotExecuted(Station Station) : StopOutcome
    {
        public override StopVerdict Verdict => StopVerdict.NotExecuted;

        public override string Text => $"{Station} acknowledged STOP but still answers in Freeport: the STOP was not executed";
    }

    /// <summary>The reply to STOP was lost and the station still answers IDENTIFY: the PLC did not act on it.</summary>
    public sealed record NotStopped(Station Station, string Cause) : StopOutcome
    {
        public override StopVerdict Verdict => StopVerdict.NotStopped;

        public override string Text => $"{Station} not stopped: the reply to STOP was lost ({Cause}) and the station still answers; send STOP again if still wanted";
    }

    /// <summary>Nothing was sent: the station could not be identified first, or the port failed before the frame left.</summary>
    public sealed record NotSent(Station Station, string Reason) : StopOutcome
    {
        public override StopVerdict Verdict => StopVerdict.NotSent;

        public override string Text => $"{Station}: STOP not sent: {Reason}";
    }

    /// <summary>The station's handler was generated without STOP (IDENTIFY FEATURES bit 0 clear): nothing was sent.</summary>
    public sealed record NotInHandler(Station Station) : StopOutcome
    {
        public override StopVerdict Verdict => StopVerdict.NotInHandler;

        public override string Text =>
            $"{Station}: its handler was generated without STOP (IDENTIFY FEATURES bit 0 is 0), nothing sent; set \"allowStop\": true "
            + "for the station in the project (or opanel generate --allow-stop), generate the PLC code again and download it";
    }

    /// <summary>The station's IDENTIFY does not fit the CPU expected there (the project's, or --cpu): nothing was sent.</summary>
    public sealed record WrongCpu(Station Station, string Expected, string Mismatch) : StopOutcome
    {
        public override StopVerdict Verdict => StopVerdict.WrongCpu;

        public override string Text => $"{Station}: STOP not sent: it is not the {Expected} expected there ({Mismatch}); check the station address and the CPU";
    }

    /// <summary>The station answered STOP with an error status: it did not stop.</summary>
    public sealed record Refused(Station Station, string Error) : StopOutcome
    {
        public override StopVerdict Verdict => StopVerdict.Refused;

        public override string Text => $"{Station} refused STOP: {Error}";
    }

    /// <summary>The reply to STOP was lost and the check failed too: look at the PLC.</summary>
    public sealed record Unknown(Station Station, string Cause, string Detail) : StopOutcome
    {
        public override StopVerdict Verdict => StopVerdict.Unknown;

        public override string Text =>
            $"{Station}: unknown whether stopped: the reply to STOP was lost ({Cause}) and the check failed too ({Detail}); look at the CPU's RUN/STOP LED before sending STOP again";
    }
}
