using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// A link failure as a technician acts on it: what happened (the link's own words, which already name the station and
/// port) and what to check for that kind of failure. Text: two lines on stderr; JSON: error, kind and hint.
/// </summary>
/// <param name="Error">What happened, e.g. "station 5 on COM3: no valid reply to Read after 2 attempts (...)".</param>
/// <param name="Kind">The failure's kind (noAnswer, portUnavailable, frameCorrupt, ...); null when not known.</param>
/// <param name="Hint">What to check next; null when the error already says it.</param>
internal sealed record LinkFailure(string Error, PlcErrorKind? Kind, string? Hint)
{
    public static LinkFailure From(LinkTarget target, PlcCommunicationException failure) =>
        new(failure.Message, failure.Kind, HintFor(target, failure.Kind));

    /// <summary>From a station's last error as the polling engine keeps it ("NoAnswer: station 5 on COM3: ...").</summary>
    public static LinkFailure From(LinkTarget target, string? lastError, PlcErrorKind? kind) =>
        new(WithoutKind(lastError, kind) ?? "no reply", kind, HintFor(target, kind));

    /// <summary>"PortUnavailable: serial port COM3: ..." without the kind's name: the words say it (the kind is for --json).</summary>
    public static string? WithoutKind(string? error, PlcErrorKind? kind) =>
        error is not null && kind is { } k && error.StartsWith($"{k}: ", StringComparison.Ordinal) ? error[$"{k}: ".Length..] : error;

    public static string? HintFor(LinkTarget target, PlcErrorKind? kind)
    {
        ArgumentNullException.ThrowIfNull(target);
        if (target.Serial.Protocol == LinkProtocol.Ppi && PpiHintFor(target, kind) is { } ppi)
        {
            return ppi;
        }

        var station = target.Station.Address;
        var line = target.Serial.LineText;
        return kind switch
        {
            PlcErrorKind.NoAnswer or PlcErrorKind.Timeout =>
                $"nothing answers as station {station}: check that the PLC is in RUN with its mode switch at RUN (at TERM or in STOP "
                + $"its port speaks PPI to Micro/WIN, not to the panel), that its handler was generated for station {station} at {line} "
                + $"(the top of the {target.NotesFile ?? "NAME-README.txt"} that opanel generate wrote beside the handler), that OB1 calls OP_PANEL every scan, and the cable or radio module "
                + "(a station still running a protocol v1 or v2 handler is silent behind radio modules: regenerate its PLC code)",
            PlcErrorKind.PortUnavailable =>
                $"check the port name ({target.Serial.PortName}), that the cable or USB adapter is plugged in, and that no other "
                + "program (Micro/WIN, another opanel) has the port open",
            PlcErrorKind.FrameCorrupt =>
                $"replies arrive garbled: check that {line} is the handler's setting (--baud, --parity, --data-bits), that no "
                + $"other PLC on the bus also has station number {station}, and the RS-485 wiring",
            PlcErrorKind.AnotherMaster =>
                "another PPI master (Micro/WIN, a TD 200, an HMI or a CPU in PPI master mode) is on the bus: the panel does not share "
                + "the bus with another master; disconnect it or give the panel its own port",
            PlcErrorKind.NegativeReply or PlcErrorKind.HandlerOutdated or null => null,
        };
    }

    /// <summary>
    /// On a PPI bus no program of ours is in the CPU: the checks are the CPU's port settings (system block), the cable and
    /// the bus, never the handler (docs/ppi.md sections 4 and 14). Null where the Freeport hint fits PPI as well (the port,
    /// another master).
    /// </summary>
    private static string? PpiHintFor(LinkTarget target, PlcErrorKind? kind)
    {
        var station = target.Station.Address;
        var baud = target.Serial.BaudRate;
        return kind switch
        {
            PlcErrorKind.NoAnswer =>
                $"nothing answers at PPI address {station}: check the CPU's port settings in its system block (PPI address {station}, "
                + $"{baud} baud; PPI is always 8 data bits, even parity), the PC/PPI cable's baud switches, that no program holds the "
                + "port in Freeport (with its mode switch at RUN a Freeport program's port does not speak PPI; in STOP or at TERM it "
                + "does), and the cable",
            PlcErrorKind.Timeout =>
                $"the CPU at PPI address {station} took the job but its answer did not come within the time allowed: a CPU answers "
                + "after its scan, so allow for a long scan with --scan-ms",
            PlcErrorKind.FrameCorrupt =>
                $"the answers were garbled or not the answer to this job: check that the CPU's port runs PPI at {baud} baud, that no "
                + $"other station on the bus has PPI address {station}, and the RS-485 wiring; a ReferenceMismatch is a late answer "
                + "to an earlier job, which a slow or busy line explains (try again, or a longer --scan-ms)",
            _ => null,
        };
    }

    /// <summary>Prints the failure (stderr, or a JSON object on stdout with --json) and returns <see cref="ExitCodes.LinkFailure"/>.</summary>
    public int Report(CliContext cli, string? suffix = null)
    {
        var error = suffix is null ? Error : $"{Error}; {suffix}";
        if (cli.Json)
        {
            cli.WriteJson(new { ok = false, error, kind = Kind is { } k ? System.Text.Json.JsonNamingPolicy.CamelCase.ConvertName(k.ToString()) : null, hint = Hint });
            return ExitCodes.LinkFailure;
        }

        cli.Error.WriteLine($"opanel: {error}");
        if (Hint is not null)
        {
            cli.Error.WriteLine($"opanel: {Hint}");
        }

        return ExitCodes.LinkFailure;
    }
}
