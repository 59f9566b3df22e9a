using System.CommandLine;
using System.Globalization;
using OperatorPanel.Cli.Bench;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// <c>opanel bench stl [--requests N] [--baud B]</c>: how fast the STL interpreter runs the generated handler in real
/// time: requests served per real second, real time per request (the 255-character WRITE among them), and how many
/// times faster than the real line and PLC that is. Exit 0, or 1 for a bad option or a handler that cannot be generated.
/// </summary>
internal static class StlBenchCommand
{
    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var requests = new Option<int>("--requests") { Description = "Requests per workload (default 200)", DefaultValueFactory = _ => 200 };
        var baud = new Option<int>("--baud") { Description = "Freeport baud rate of the simulated line (default 9600)", DefaultValueFactory = _ => 9600 };
        var command = new Command("stl", "Real-time speed of the STL interpreter running the generated CPU 224 handler") { requests, baud };
        command.SetAction(parse =>
        {
            var cli = context(parse);
            var count = parse.GetValue(requests);
            if (count < 1)
            {
                return cli.Fail(ExitCodes.BadInput, $"--requests {count}: give at least 1");
            }

            if (!StlBench.TryRun(parse.GetValue(baud), count, TimeProvider.System, out var results, out var error))
            {
                return cli.Fail(ExitCodes.BadInput, error);
            }

            if (cli.Json)
            {
                cli.WriteJson(results.Select(r => new
                {
                    r.Workload,
                    r.RequestChars,
                    r.ReplyChars,
                    r.Requests,
                    r.Answered,
                    r.RequestsPerRealSecond,
                    r.RealMsPerRequest,
                    r.SimulatedMsPerRequest,
                    r.SpeedFactor,
                    r.InstructionsPerRequest,
                }));
                return ExitCodes.Ok;
            }

            cli.Out.WriteLine($"STL interpreter, generated CPU 224 handler, {parse.GetValue(baud)} 8N1, {count} requests per workload");
            cli.Out.WriteLine("workload          req chars  reply chars  answered  req/s real  real ms/req  simulated ms/req  x real time  instr/req");
            foreach (var r in results)
            {
                cli.Out.WriteLine(string.Create(
                    CultureInfo.InvariantCulture,
                    $"{r.Workload,-17} {r.RequestChars,9}  {r.ReplyChars,11}  {r.Answered,8}  {r.RequestsPerRealSecond,10:F0}  {r.RealMsPerRequest,11:F3}  {r.SimulatedMsPerRequest,16:F2}  {r.SpeedFactor,11:F1}  {r.InstructionsPerRequest,9:F0}"));
            }

            return ExitCodes.Ok;
        });
        return command;
    }
}
