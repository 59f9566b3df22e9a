using System.CommandLine;
using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Cli.Commands;

/// <summary><c>opanel read ADDR... --device DEV --station N</c>: one refresh of the given addresses, one line each.</summary>
internal static class ReadCommand
{
    /// <summary>Room for a double word in decimal (4294967295), so plain reads line up as they always did.</summary>
    private const int MinimumValueWidth = 11;

    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var addresses = new Argument<string[]>("address")
        {
            Description = "Addresses to read: I0.0, QB0, MW10, VD100, SMB28 ...; ADDR:real, :signed, :hex, :binary or :ascii shows the value so (VD16:real, MW2:signed); "
                + "with --project also the station's symbols (BottleCount), shown in the tag's format, scaled, with its unit",
            Arity = ArgumentArity.OneOrMore,
        };
        var link = new LinkOptionSet();
        var command = new Command(
            "read",
            "Read addresses from a PLC once and print address, value (unsigned decimal and hex; 0/1 for a bit) and quality. "
            + "Every bad argument is reported and nothing is read then. Exit codes: 0 read, 1 bad address or refused by the PLC, 2 link failure")
        {
            addresses,
        };
        link.AddTo(command);
        command.SetAction(async (parse, cancellationToken) =>
        {
            var cli = context(parse);
            if (!link.TryBind(parse, cli, out var target, out var station))
            {
                return ExitCodes.BadInput;
            }

            var parsed = new List<(ArgumentTarget Target, DisplayFormat? Format)>();
            var errors = new List<string>();
            foreach (var text in parse.GetValue(addresses) ?? [])
            {
                if (!ReadFormats.TrySplit(text, out var addressText, out var format, out var error)
                    || !ArgumentTarget.TryResolve(addressText, target, station, AddressUse.Read, out var resolved, out error)
                    || !ReadFormats.TryCheck(resolved.Address, format, text, out error))
                {
                    errors.Add(error);
                    continue;
                }

                parsed.Add((resolved, format));
            }

            return errors.Count > 0
                ? cli.FailAll(ExitCodes.BadInput, errors, "nothing read")
                : await ReadAsync(cli, target, parsed, cancellationToken);
        });
        return command;
    }

    private static async Task<int> ReadAsync(CliContext cli, LinkTarget target, List<(ArgumentTarget Target, DisplayFormat? Format)> addresses, CancellationToken cancellationToken)
    {
        if (!LinkSession.TryOpen(target, PlanFor(target, addresses.Select(a => a.Target.Address)), cli, out var opened, out var openError))
        {
            return cli.Fail(ExitCodes.BadInput, openError);
        }

        await using var session = opened;
        await session.ResolveCutShortAsync(cli, cancellationToken);
        await session.Bus.RefreshAsync(cancellationToken);
        var status = session.Bus.StatusOf(target.Station);
        if (status.State != StationState.Online)
        {
            return LinkFailure.From(target, status.LastError, status.LastErrorKind).Report(cli);
        }

        var views = addresses.Distinct().Select(a => ReadValueView.From(a.Target, session.Bus.TryGetValue(target.Station, a.Target.Address, out var v) ? v : null, a.Format)).ToList();
        if (cli.Json)
        {
            cli.WriteJson(views);
        }
        else
        {
            var width = Math.Max(MinimumValueWidth, views.Max(v => v.ValueText().Length));
            views.ForEach(v => v.WriteText(cli.Out, width));
        }

        return views.All(v => v.Quality == "good") ? ExitCodes.Ok : ExitCodes.BadInput;
    }

    internal static PollPlan PlanFor(LinkTarget target, IEnumerable<PlcAddress> addresses) =>
        new ProjectBus(target.Serial, []).Plan(addresses.Select(a => new WatchedItem(target.Station, a)),
            target.Cpu is null ? null : new Dictionary<Core.Addressing.Station, Core.Cpu.CpuProfile> { [target.Station] = target.Cpu });
}
