using System.CommandLine;
using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Stop;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// <c>opanel stop --device DEV --station N --yes</c> (or <c>--project FILE</c>): puts the PLC into STOP over Freeport (docs/protocol-v2.md, "07 STOP")
/// through <see cref="RemoteStop"/>: IDENTIFY first (FEATURES bit 0, else nothing is sent), 07 once, then IDENTIFY
/// again, whose silence confirms it. Without --yes it only says what it would do.
/// </summary>
internal static class StopCommand
{
    private const string Description =
        "Put a PLC into STOP: the line stops and the port returns to PPI until someone sets RUN (mode switch or Micro/WIN). "
        + "Needs --yes; without it nothing is sent. With --project the station (--station ADDRESS or NAME, or the only one) must have \"allowStop\": true, "
        + "and its port, line settings and CPU come from the project unless --device, --demo or --cpu say otherwise. The station's handler must be generated with STOP (\"allowStop\": true in the "
        + "project, or opanel generate --allow-stop): IDENTIFY is asked first, and without FEATURES bit 0 nothing is sent; nor when the CPU it reports (SMB6, and the CPU "
        + "the handler was generated for) is not the project's or --cpu's. "
        + "STOP is sent once, never repeated, and logged (\"station N RUN -> STOP by operator\"); an IDENTIFY afterwards must get no "
        + "answer to confirm it. A lost reply is settled the same way: no answer = stopped (reply lost, station silent), an answer = not stopped. "
        + "Exit codes: 0 stopped; 1 bad input, or nothing sent because the project does not allow STOP, the handler has no STOP, the CPU is not the expected one or the PLC refused it; 2 not stopped "
        + "(nothing sent on a link failure, the station still answers after STOP); 3 unknown whether stopped; 4 not confirmed with --yes, nothing sent";

    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var link = new LinkOptionSet();
        var yes = new Option<bool>("--yes") { Description = "Confirm the STOP: without it opanel says what it would do and sends nothing" };
        var command = new Command("stop", Description) { yes };
        link.AddTo(command);
        command.SetAction(async (parse, cancellationToken) =>
        {
            var cli = context(parse);
            if (!link.TryBind(parse, cli, out var target, out var station))
            {
                return ExitCodes.BadInput;
            }

            if (station is { AllowStop: false })
            {
                return cli.Fail(
                    ExitCodes.BadInput,
                    $"the project does not allow STOP for {station.Name} ({station.Address}): set \"allowStop\": true for it in {parse.GetValue(link.Project)}, "
                    + "generate the PLC code again and download it; nothing sent");
            }

            if (!parse.GetValue(yes))
            {
                return cli.Fail(
                    ExitCodes.StopNotConfirmed,
                    $"this would put {target.Describe()} into STOP: its program stops, the line stops, and its port returns to PPI "
                    + "until someone sets RUN. Nothing sent; to do it, give the same command with --yes");
            }

            if (!LinkSession.TryOpen(target, PollPlan.Empty, cli, out var opened, out var openError))
            {
                return cli.Fail(ExitCodes.BadInput, openError);
            }

            await using var session = opened;
            await session.ResolveCutShortAsync(cli, cancellationToken);
            var outcome = await session.Bus.StopAsync(target.Station, target.Cpu, cancellationToken);
            var view = StopResultView.From(target, outcome);
            if (cli.Json)
            {
                cli.WriteJson(view);
            }
            else
            {
                cli.Out.WriteLine(view.Message);
            }

            return view.ExitCode;
        });
        return command;
    }
}
