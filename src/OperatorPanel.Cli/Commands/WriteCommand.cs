using System.CommandLine;
using OperatorPanel.Cli.Hosting;
using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Polling;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// <c>opanel write ADDR=VALUE...</c>: every value is checked first (nothing is written if any is bad), then the current
/// values are read once (so the log and the output show old and new), then each write is sent and judged by its read-back.
/// </summary>
internal static class WriteCommand
{
    private const string Description =
        "Write values to a PLC, each confirmed by the PLC's read-back; prints old -> new and confirmed, mismatch (read back X) or failed: reason. "
        + "A write whose reply is lost is never sent again: the panel reads the address back and prints confirmed (reply lost, read back), "
        + "not applied (the old value is still there: write again if still wanted) or unknown (check the value before writing again). "
        + "Every write is logged with old and new value. Every bad assignment is reported, and then nothing is written. "
        + "VALUE notation: a bit takes 0/1, true/false, on/off; 16#FF or 0xFF is hex, 2#1010 binary, 'AB' or \"AB\" ASCII of exactly "
        + "the width's length, a number with '.' or an exponent a REAL (double words only), a leading '-' a signed number, anything else unsigned. "
        + "A REAL is written as the nearest REAL and confirmed against it; one the PLC cannot hold (0 or ±1.175495E-38 to ±3.402823E+38: "
        + "1.5e-50 would be stored as 0) is bad input, as are the handler's own V bytes and, with --project, any byte of a tag it marks read-only. "
        + "Exit codes: 0 all confirmed; 1 bad input (address, value, refused by the panel's write rules) or refused by the PLC (not writable, "
        + "out of range), nothing written for bad input; 2 not applied (nothing sent, or the old value read back after a lost reply) or read back differently; "
        + "3 unknown whether applied (3 wins over 2, 2 over 1); 130 interrupted by Ctrl+C or SIGTERM: the write on the wire is finished and "
        + "read back, every outcome is printed, the writes after it are not sent (3 wins over 130). Each write's intent is in the write "
        + "journal before its frame leaves, and its outcome after; a write cut short by a kill is settled at the next start";

    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var assignments = new Argument<string[]>("assignment")
        {
            Description = "ADDR=VALUE, e.g. VW200=1234 Q0.1=on VD120=12.5 VB110=16#2A VD130='AB12'; with --project also SYMBOL=VALUE "
                + "in the tag's units (RecipeNumber=3, TankLevel=55.2), and a tag's min/max and read-only flag hold however the cell is named",
            Arity = ArgumentArity.OneOrMore,
        };
        var link = new LinkOptionSet();
        var command = new Command("write", Description) { assignments };
        link.AddTo(command);
        command.SetAction(async (parse, cancellationToken) =>
        {
            var cli = context(parse);
            if (!link.TryBind(parse, cli, out var target, out var fromProject))
            {
                return ExitCodes.BadInput;
            }

            var items = new List<WriteItem>();
            var errors = new List<string>();
            foreach (var text in parse.GetValue(assignments) ?? [])
            {
                if (WriteItem.TryParse(text, target, fromProject, out var item, out var error))
                {
                    items.Add(item);
                }
                else
                {
                    errors.Add(error);
                }
            }

            return errors.Count > 0
                ? cli.FailAll(ExitCodes.BadInput, errors, "nothing written")
                : await WriteAsync(cli, target, items, cancellationToken);
        });
        return command;
    }

    private static async Task<int> WriteAsync(CliContext cli, LinkTarget target, List<WriteItem> items, CancellationToken cancellationToken)
    {
        if (!LinkSession.TryOpen(target, ReadCommand.PlanFor(target, items.Select(i => i.Address)), cli, out var opened, out var openError))
        {
            return cli.Fail(ExitCodes.BadInput, openError);
        }

        // Ctrl+C (or SIGTERM) lets the write on the wire finish and be read back: it is never abandoned half-way.
        using var stop = new StopSignals(null, () => cli.Error.WriteLine(
            "opanel: stopping after the write on the wire (Ctrl+C again quits at once; that write is then settled at the next start)"));
        await using var session = opened;
        await session.ResolveCutShortAsync(cli, cancellationToken);
        try
        {
            await session.Bus.RefreshAsync(stop.Token);
        }
        catch (OperationCanceledException) when (stop.IsStopRequested)
        {
            return cli.Fail(ExitCodes.Interrupted, "interrupted before the first write; nothing written");
        }

        var status = session.Bus.StatusOf(target.Station);
        if (status.State != StationState.Online)
        {
            return LinkFailure.From(target, status.LastError, status.LastErrorKind).Report(cli, "nothing written");
        }

        var results = new List<WriteResultView>();
        foreach (var item in items)
        {
            var old = session.Bus.TryGetValue(target.Station, item.Address, out var value) ? value : null;
            if (stop.IsStopRequested)
            {
                results.Add(WriteResultView.NotSent(item, old, "interrupted (Ctrl+C) before it was sent"));
                continue;
            }

            var outcome = await session.Bus.WriteAsync(item.Request, CancellationToken.None);
            results.Add(WriteResultView.From(item, old, outcome));
        }

        if (cli.Json)
        {
            cli.WriteJson(results);
        }
        else
        {
            results.ForEach(r => r.WriteText(cli.Out));
        }

        return ExitCodeOf(results, stop.IsStopRequested);
    }

    /// <summary>3 (unknown whether applied) first: it asks for a look at the PLC; then 130 when interrupted; else the worst.</summary>
    private static int ExitCodeOf(List<WriteResultView> results, bool interrupted) =>
        results.Any(r => r.ExitCode == ExitCodes.WriteUnknown) ? ExitCodes.WriteUnknown
        : interrupted ? ExitCodes.Interrupted
        : results.Max(r => r.ExitCode);
}
