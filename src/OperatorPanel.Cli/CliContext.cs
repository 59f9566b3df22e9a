using System.Text.Encodings.Web;
using System.Text.Json;
using System.Text.Json.Serialization;
using OperatorPanel.Cli.Logging;
using OperatorPanel.Core.Audit;
using OperatorPanel.Historian;
using Serilog;

namespace OperatorPanel.Cli;

/// <summary>What every verb gets: where to print, whether to print JSON, and the log.</summary>
internal sealed record CliContext(TextWriter Out, TextWriter Error, bool Json, ILogger Log)
{
    private static readonly JsonSerializerOptions JsonLineOptions = new()
    {
        // Lamps (● ○) stay readable; the stream is never embedded in HTML.
        Encoder = JavaScriptEncoder.UnsafeRelaxedJsonEscaping,
        PropertyNamingPolicy = JsonNamingPolicy.CamelCase,
        Converters = { new JsonStringEnumConverter() },
    };

    private static readonly JsonSerializerOptions JsonOptions = new()
    {
        // Messages quote addresses ('M10.8') and use apostrophes: kept as typed, not as \u0027; never embedded in HTML.
        Encoder = JavaScriptEncoder.UnsafeRelaxedJsonEscaping,
        WriteIndented = true,
        PropertyNamingPolicy = JsonNamingPolicy.CamelCase,
        Converters = { new JsonStringEnumConverter() },
    };

    /// <summary>Where the projects' history databases are (--history-dir, default the user's local application data folder).</summary>
    public HistoryFolder History { get; init; } = HistoryFolder.Default;

    /// <summary>True when stdout is the console itself, not a pipe, a file or a test's writer: live views redraw in place.</summary>
    public bool IsTerminal { get; init; }

    /// <summary>
    /// The write journal beside the logs (--log-dir, default the user's OperatorPanel/logs, shared with the app): every
    /// write and STOP goes on record there before it is sent.
    /// </summary>
    public WriteJournal Journal { get; init; } = WriteJournal.In(CliLogging.DefaultLogFolder);

    public void WriteJson<T>(T value) => Out.WriteLine(JsonSerializer.Serialize(value, JsonOptions));

    /// <summary>One compact JSON object on one line (JSON lines), flushed, for streams such as watch and simulate.</summary>
    public void WriteJsonLine<T>(T value)
    {
        Out.WriteLine(JsonSerializer.Serialize(value, JsonLineOptions));
        Out.Flush();
    }

    /// <summary>
    /// Reports every bad argument at once, one a line ("opanel: 'VB99999': ..."), then what was not done ("nothing
    /// written"); with --json one object with all of them.
    /// </summary>
    public int FailAll(int exitCode, IReadOnlyList<string> errors, string consequence)
    {
        var summary = errors.Count == 1 ? consequence : $"{errors.Count} arguments are wrong; {consequence}";
        if (Json)
        {
            WriteJson(new { ok = false, error = errors.Count == 1 ? $"{errors[0]}; {consequence}" : summary, errors });
            return exitCode;
        }

        if (errors.Count == 1)
        {
            Error.WriteLine($"opanel: {errors[0]}; {consequence}");
            return exitCode;
        }

        foreach (var error in errors)
        {
            Error.WriteLine($"opanel: {error}");
        }

        Error.WriteLine($"opanel: {summary}");
        return exitCode;
    }

    /// <summary>
    /// Reports a command line that could not be parsed: each problem on stderr ("opanel: --duration abc: give a number of
    /// seconds") and where to read more, never the whole help text; with --json one object on stdout, as <see cref="FailAll"/>
    /// writes it, plus the hint.
    /// </summary>
    public int FailCommandLine(IReadOnlyList<string> errors, string hint)
    {
        if (Json)
        {
            WriteJson(new { ok = false, error = errors.Count == 1 ? errors[0] : $"{errors.Count} problems on the command line", errors, hint });
            return ExitCodes.BadInput;
        }

        foreach (var error in errors)
        {
            Error.WriteLine($"opanel: {error}");
        }

        Error.WriteLine($"opanel: {hint}");
        return ExitCodes.BadInput;
    }

    /// <summary>Reports bad input: a JSON object on stdout with --json, otherwise the message on stderr.</summary>
    public int Fail(int exitCode, string message)
    {
        if (Json)
        {
            WriteJson(new { ok = false, error = message });
        }
        else
        {
            Error.WriteLine($"opanel: {message}");
        }

        return exitCode;
    }
}
