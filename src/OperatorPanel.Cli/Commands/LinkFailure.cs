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
        var station = target.Station.Address;
        var line = target.Serial.LineText;
        return kind switch
        {
            PlcErrorKind.NoAnswer or PlcErrorKind.Timeout =>
                $"nothing answers as station {station}: check that the PLC is in RUN with its mode switch at RUN (at TERM or in STOP "
                + $"its port speaks PPI to Micro/WIN, not to the panel), that its handler was generated for station {station} at {line} "
                + $"(the top of the {target.NotesFile ?? "NAME-README.txt"} that opanel generate wrote beside the handler), that OB1 calls OP_PANEL every scan, and the cable or radio module",
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
