using System.CommandLine;
using System.CommandLine.Invocation;
using OperatorPanel.Cli.Commands;
using OperatorPanel.Cli.Logging;
using OperatorPanel.Core.Audit;
using OperatorPanel.Historian;
using Serilog.Core;
using Serilog.Events;

namespace OperatorPanel.Cli;

/// <summary>Builds the opanel command tree and runs it; Program and the tests both call <see cref="Run"/>.</summary>
internal static class OpanelApp
{
    public static int Run(string[] args, TextWriter output, TextWriter error)
    {
        var options = new GlobalOptions();
        var root = new RootCommand("opanel: operator and diagnostic panel for Siemens S7-200 PLCs (headless front end)");
        options.AddTo(root);

        foreach (var verb in Verbs(options, output, error))
        {
            root.Subcommands.Add(verb);
        }

        var parse = root.Parse(args);
        if (parse.Action is ParseErrorAction)
        {
            // Our own report instead of System.CommandLine's (its messages name .NET types, then dump the help): the
            // same for every verb, and JSON with --json. --help with a bad argument still shows the help (HelpAction).
            var cli = new CliContext(output, error, options.IsJson(parse), Logger.None);
            return cli.FailCommandLine(CommandLineErrors.Describe(parse), CommandLineErrors.Hint(parse));
        }

        // Long-running verbs (simulate, watch) handle Ctrl+C and SIGTERM themselves (Hosting/StopSignals) to print a summary.
        var invocation = new InvocationConfiguration { Output = output, Error = error, ProcessTerminationTimeout = null };
        return parse.Invoke(invocation);
    }

    private static IEnumerable<Command> Verbs(GlobalOptions options, TextWriter output, TextWriter error)
    {
        Func<ParseResult, CliContext> context = parse => options.CreateContext(parse, output, error);
        yield return CpusCommand.Create(context);
        yield return AddressCommand.Create(context);
        yield return ProjectCommand.Create(context);
        yield return ReadCommand.Create(context);
        yield return WriteCommand.Create(context);
        yield return StopCommand.Create(context);
        yield return IdentifyCommand.Create(context);
        yield return SimulateCommand.Create(context);
        yield return WatchCommand.Create(context);
        yield return HistoryCommand.Create(context);
        yield return TrendCommand.Create(context);
        yield return BenchCommand.Create(context);
        yield return GenerateCommand.Create(context);
        yield return StlCommand.Create(context);
        yield return SoakCommand.Create(context);
    }
}

/// <summary>Options every verb takes: --json, the log levels and folder, and the history folder.</summary>
internal sealed class GlobalOptions
{
    private readonly Option<bool> _json = new("--json") { Description = "Print machine-readable JSON on stdout", Recursive = true };

    private readonly Option<LogEventLevel> _logLevel = new("--log-level")
    {
        Description = "Level written to the log file",
        DefaultValueFactory = _ => LogEventLevel.Information,
        Recursive = true,
    };

    private readonly Option<LogEventLevel> _consoleLevel = new("--console-level")
    {
        // Error, not Warning: every warning of a verb (a write's read-back, a silent station) is in its own output already;
        // echoed too, each fact came out two or three times and scribbled over watch's live view.
        Description = "Level echoed to stderr (default Error: what a verb prints says the rest; Warning adds the log's warnings)",
        DefaultValueFactory = _ => LogEventLevel.Error,
        Recursive = true,
    };

    private readonly Option<string?> _logDir = new("--log-dir")
    {
        Description = "Folder for the rolling log files (default: the user's local application data folder)",
        Recursive = true,
    };

    private readonly Option<string?> _historyDir = new("--history-dir")
    {
        Description = "Folder of the projects' history databases (default: OperatorPanel/history in the user's local application data folder)",
        Recursive = true,
    };

    public void AddTo(RootCommand root)
    {
        root.Options.Add(_historyDir);
        root.Options.Add(_json);
        root.Options.Add(_logLevel);
        root.Options.Add(_consoleLevel);
        root.Options.Add(_logDir);
    }

    /// <summary>
    /// Whether --json was given, even on a command line that did not parse: its report is JSON too. A --json whose own
    /// value could not be read still asked for JSON.
    /// </summary>
    public bool IsJson(ParseResult parse) => parse.GetResult(_json) switch
    {
        null => false,
        var json when json.Errors.Any() => true,
        var json => json.GetValueOrDefault<bool>(),
    };

    public CliContext CreateContext(ParseResult parse, TextWriter output, TextWriter error)
    {
        var log = CliLogging.Create(parse.GetValue(_logLevel), parse.GetValue(_consoleLevel), parse.GetValue(_logDir));
        return new CliContext(output, error, parse.GetValue(_json), log)
        {
            IsTerminal = ReferenceEquals(output, Console.Out) && !Console.IsOutputRedirected,
            Journal = WriteJournal.In(parse.GetValue(_logDir) ?? CliLogging.DefaultLogFolder),
            History = parse.GetValue(_historyDir) is { } folder ? new HistoryFolder(folder) : HistoryFolder.Default,
        };
    }
}
