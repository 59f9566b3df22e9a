using System.CommandLine;
using OperatorPanel.Cli.Bench;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// <c>opanel bench link [--cycles N]</c> (and <c>bench stl</c>, <see cref="StlBenchCommand"/>): the modeled cost of a full refresh of the reference line against one item per
/// request and the data-only lower bound, the targets judged PASS/FAIL, then the round trip measured over a socat pty.
/// Exit 0 when both parts ran (a FAIL target is a finding, printed, not an error); 1 when socat is missing or
/// --cycles is bad; 2 when the measured run failed or no frame got a reply (lost frames are counted in the output).
/// </summary>
internal static class BenchCommand
{
    public const string SocatMissing = "socat not found: measured round trip skipped";

    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var command = new Command("bench", "Print figures about the panel's link (modeled and measured)");
        command.Subcommands.Add(CreateLink(context));
        command.Subcommands.Add(StlBenchCommand.Create(context));
        return command;
    }

    private static Command CreateLink(Func<ParseResult, CliContext> context)
    {
        var cycles = new Option<int>("--cycles")
        {
            Description = "Full refreshes for the measured round trip (default 50)",
            DefaultValueFactory = _ => 50,
        };
        var command = new Command("link", "Bytes, frames and refresh time of the reference line per strategy; targets; measured round trip")
        {
            cycles,
        };
        command.SetAction(async (parse, cancellationToken) =>
        {
            var cli = context(parse);
            var count = parse.GetValue(cycles);
            if (count < 1)
            {
                return cli.Fail(ExitCodes.BadInput, $"--cycles {count}: give at least 1 refresh");
            }

            var line = ReferenceLine.Create();
            var report = LinkBenchReport.Create(line, ExchangeTiming.Default);
            var socat = SocatPty.Find();
            MeasuredRoundTrip? measured = null;
            try
            {
                measured = socat is null ? null : await LinkRoundTrip.MeasureAsync(line, count, socat, TimeProvider.System, cancellationToken);
            }
            catch (Exception exception) when (exception is PlcCommunicationException or InvalidOperationException or TimeoutException)
            {
                if (!cli.Json)
                {
                    LinkBenchText.WriteModeled(cli.Out, report);
                }

                return cli.Fail(ExitCodes.LinkFailure, $"measured round trip failed: {exception.Message}");
            }

            Print(cli, report, measured);
            cli.Log.Information("bench link: {Targets}", string.Join(", ", report.Targets.Select(t => $"{t.Name} {t.Verdict}")));
            return measured is null ? ExitCodes.BadInput
                : measured.FramesFailed == measured.Cycles * measured.FramesPerRefresh ? ExitCodes.LinkFailure
                : ExitCodes.Ok;
        });
        return command;
    }

    private static void Print(CliContext cli, LinkBenchReport report, MeasuredRoundTrip? measured)
    {
        if (cli.Json)
        {
            cli.WriteJson(LinkBenchJson.From(report, measured, measured is null ? SocatMissing : null));
            return;
        }

        LinkBenchText.WriteModeled(cli.Out, report);
        if (measured is null)
        {
            cli.Out.WriteLine();
            cli.Out.WriteLine(SocatMissing);
            cli.Error.WriteLine($"opanel: {SocatMissing}");
        }
        else
        {
            LinkBenchText.WriteMeasured(cli.Out, measured);
        }
    }
}
