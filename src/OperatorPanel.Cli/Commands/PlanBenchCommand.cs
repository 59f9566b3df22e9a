using System.CommandLine;
using System.Globalization;
using OperatorPanel.Cli.Bench;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// <c>opanel bench plan [--tags 200,2000,20000] [--runs N]</c>: how long the poll planner takes for 200, 2000 and 20000
/// scattered tags on one station (median of N runs after a warm-up) and what it allocates. A size whose run takes
/// longer than a minute is run once and the larger sizes are skipped (named in the output). Exit 0, or 1 for a bad option.
/// </summary>
internal static class PlanBenchCommand
{
    private static readonly TimeSpan SlowRun = TimeSpan.FromMinutes(1);

    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var tags = new Option<int[]>("--tags")
        {
            Description = "Tag counts to plan (default 200 2000 20000)",
            DefaultValueFactory = _ => PlanBench.DefaultSizes,
            AllowMultipleArgumentsPerToken = true,
        };
        var runs = new Option<int>("--runs") { Description = "Timed runs per tag count (default 7)", DefaultValueFactory = _ => 7 };
        var command = new Command("plan", "Plan time and allocations of the poll planner for scattered tags on one station") { tags, runs };
        command.SetAction(parse =>
        {
            var cli = context(parse);
            var (sizes, count) = (parse.GetValue(tags)!, parse.GetValue(runs));
            if (count < 1)
            {
                return cli.Fail(ExitCodes.BadInput, $"--runs {count}: give at least 1");
            }

            if (sizes.Length == 0 || sizes.Any(s => s is < 1 or > 50_000))
            {
                return cli.Fail(ExitCodes.BadInput, $"--tags {string.Join(' ', sizes)}: give tag counts of 1-50000");
            }

            var results = new List<PlanTiming>();
            var skipped = new List<int>();
            foreach (var size in sizes.Order())
            {
                if (results.Count > 0 && results[^1].MaxMs > SlowRun.TotalMilliseconds)
                {
                    skipped.Add(size);
                    continue;
                }

                var probe = PlanBench.Time(size, 1, TimeProvider.System);
                results.Add(probe.MaxMs > SlowRun.TotalMilliseconds || count == 1 ? probe : PlanBench.Time(size, count, TimeProvider.System));
            }

            Print(cli, results, skipped);
            return ExitCodes.Ok;
        });
        return command;
    }

    private static void Print(CliContext cli, List<PlanTiming> results, List<int> skipped)
    {
        if (cli.Json)
        {
            cli.WriteJson(new { results, skipped });
            return;
        }

        cli.Out.WriteLine("opanel bench plan: PollPlanner.Build on one CPU 226 station, scattered I/Q/M/V tags (MEASURED on this machine)");
        cli.Out.WriteLine("    tags  runs  median ms     max ms  allocated KB  frames  values  rejected");
        foreach (var r in results)
        {
            cli.Out.WriteLine(string.Create(
                CultureInfo.InvariantCulture,
                $"  {r.Tags,6}  {r.Runs,4}  {r.MedianMs,9:0.00}  {r.MaxMs,9:0.00}  {r.AllocatedBytes / 1024.0,12:0.0}  {r.Frames,6}  {r.Values,6}  {r.Rejected,8}"));
        }

        foreach (var size in skipped)
        {
            cli.Out.WriteLine($"  {size,6}  skipped: a smaller count already took over {SlowRun.TotalSeconds:0} s a run");
        }
    }
}
