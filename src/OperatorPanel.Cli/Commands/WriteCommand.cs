using System.CommandLine;
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
        + "Every write is logged with old and new value. "
        + "VALUE notation: a bit takes 0/1, true/false, on/off; 16#FF or 0xFF is hex, 2#1010 binary, 'AB' or \"AB\" ASCII of exactly "
        + "the width's length, a number with '.' or an exponent a REAL (double words only), a leading '-' a signed number, anything else unsigned. "
        + "Exit codes: 0 all confirmed; 1 bad input (address, value) or refused by the PLC (not writable, out of range), nothing written "
        + "for bad input; 2 not applied (nothing sent, or the old value read back after a lost reply) or read back differently; "
        + "3 unknown whether applied (3 wins over 2, 2 over 1)";

    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var assignments = new Argument<string[]>("assignment")
        {
            Description = "ADDR=VALUE, e.g. VW200=1234 Q0.1=on VD120=12.5 VB110=16#2A VD130='AB12'",
            Arity = ArgumentArity.OneOrMore,
        };
        var link = new LinkOptionSet();
        var command = new Command("write", Description) { assignments };
        link.AddTo(command);
        command.SetAction(async (parse, cancellationToken) =>
        {
            var cli = context(parse);
            if (!link.TryBind(parse, cli, out var target, out _))
            {
                return ExitCodes.BadInput;
            }

            var items = new List<WriteItem>();
            foreach (var text in parse.GetValue(assignments) ?? [])
            {
                if (!WriteItem.TryParse(text, target, out var item, out var error))
                {
                    return cli.Fail(ExitCodes.BadInput, error + "; nothing written");
                }

                items.Add(item);
            }

            return await WriteAsync(cli, target, items, cancellationToken);
        });
        return command;
    }

    private static async Task<int> WriteAsync(CliContext cli, LinkTarget target, List<WriteItem> items, CancellationToken cancellationToken)
    {
        if (!LinkSession.TryOpen(target, ReadCommand.PlanFor(target, items.Select(i => i.Address)), cli.Log, out var opened, out var openError))
        {
            return cli.Fail(ExitCodes.BadInput, openError);
        }

        await using var session = opened;
        await session.Bus.RefreshAsync(cancellationToken);
        var status = session.Bus.StatusOf(target.Station);
        if (status.State != StationState.Online)
        {
            return LinkFailure.From(target, status.LastError, status.LastErrorKind).Report(cli, "nothing written");
        }

        var results = new List<WriteResultView>();
        foreach (var item in items)
        {
            var old = session.Bus.TryGetValue(target.Station, item.Address, out var value) ? value : null;
            var outcome = await session.Bus.WriteAsync(item.Request, cancellationToken);
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

        return results.Max(r => r.ExitCode);
    }
}
