using System.CommandLine;
using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Cli.Commands;

/// <summary><c>opanel identify --device DEV --station N [--cpu M]</c>: what the handler says about itself and its CPU.</summary>
internal static class IdentifyCommand
{
    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var link = new LinkOptionSet();
        var command = new Command(
            "identify",
            "Ask a PLC's handler for protocol version, handler revision, the CPU it was generated for, SMB6, mode switch, scan times, "
            + "write mask and reply delay; with --cpu, compare and print a mismatch line. With --ppi (no handler) it reads SMB6, SM0.7 and "
            + "SMW22-SMW26 instead and shows RUN/STOP as unknown. "
            + "Exit codes: 0 identified (and matching --cpu), 1 bad input or a CPU mismatch, 2 link failure");
        link.AddTo(command);
        command.SetAction(async (parse, cancellationToken) =>
        {
            var cli = context(parse);
            if (!link.TryBind(parse, cli, out var target, out _))
            {
                return ExitCodes.BadInput;
            }

            if (!LinkSession.TryOpen(target, PollPlan.Empty, cli, out var opened, out var openError))
            {
                return cli.Fail(ExitCodes.BadInput, openError);
            }

            await using var session = opened;
            await session.ResolveCutShortAsync(cli, cancellationToken);
            if (session.Bus.IsPpi)
            {
                return await IdentifyPpiAsync(cli, target, session, cancellationToken);
            }

            var reply = await session.Bus.IdentifyAsync(target.Station, cancellationToken);
            if (reply.Failure is { } failure)
            {
                return LinkFailure.From(target, failure).Report(cli);
            }

            if (reply.Response is not IdentifyResponse identity)
            {
                return cli.Fail(ExitCodes.LinkFailure, $"{target.Describe()}: IDENTIFY answered with {reply.Response}");
            }

            var view = IdentifyView.From(target, identity);
            return Print(cli, view, view.WriteText, view.CpuMismatch);
        });
        return command;
    }

    /// <summary>Over PPI there is no handler to ask: SMB6, SM0.7 and the scan times instead, RUN/STOP shown as unknown.</summary>
    private static async Task<int> IdentifyPpiAsync(CliContext cli, LinkTarget target, LinkSession session, CancellationToken cancellationToken)
    {
        var outcome = await session.Bus.IdentifyPpiAsync(target.Station, cancellationToken);
        if (outcome.Identity is not { } identity)
        {
            var status = session.Bus.StatusOf(target.Station);
            return status.State == StationState.Online
                ? cli.Fail(ExitCodes.BadInput, $"{target.Describe()}: {outcome.Error}")
                : LinkFailure.From(target, status.LastError, status.LastErrorKind).Report(cli);
        }

        var view = PpiIdentifyView.From(target, identity);
        return Print(cli, view, view.WriteText, view.CpuMismatch);
    }

    /// <summary>The view as JSON or text; exit 1 when the CPU does not match the one asked for.</summary>
    private static int Print<T>(CliContext cli, T view, Action<TextWriter> writeText, string? cpuMismatch)
    {
        if (cli.Json)
        {
            cli.WriteJson(view);
        }
        else
        {
            writeText(cli.Out);
        }

        return cpuMismatch is null ? ExitCodes.Ok : ExitCodes.BadInput;
    }
}
