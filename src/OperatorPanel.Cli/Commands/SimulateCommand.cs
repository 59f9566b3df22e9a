using System.CommandLine;
using OperatorPanel.Cli.Hosting;
using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.Demo;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// <c>opanel simulate --cpu M --station N [--station N2 ...] --device PATH</c>, or <c>opanel simulate --project FILE --device
/// PATH</c> for a project's bus (each station with its own CPU): simulated PLCs with the protocol handler on a real serial
/// device (a USB-RS485 adapter, or one end of a socat pty pair), until Ctrl+C, SIGTERM or --duration. With --ppi the
/// CPUs run no handler and their ports speak PPI (docs/ppi.md section 11). The handler options are opanel generate's
/// (--plc-port, --buffer, --reply-delay, --writable, --char-timeout, --sbr, --int, --copy-bytes, --allow-stop; one
/// definition, <see cref="HandlerOptionSet"/>), so a simulated station runs the handler generate writes for them.
/// </summary>
internal static class SimulateCommand
{
    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var cpu = CpuOptions.Model(required: false);
        var revision = CpuOptions.Revision();
        var stations = new Option<int[]>("--station") { Description = "Station address to simulate, 1-126; repeat for several PLCs on the bus (with --project: which of its stations, default all)" };
        var project = new Option<string?>("--project")
        {
            Description = "Simulate a project's bus: its stations (or those given with --station), each with its own CPU and \"allowStop\", at the bus's baud rate, parity and data bits",
        };
        var serial = new SerialOptionSet(panelSide: false);
        var handler = new HandlerOptionSet();
        var noProcess = new Option<bool>("--no-process") { Description = "Do not run the demo bottling process: memory stays as the panel writes it" };
        var duration = new Option<double?>("--duration") { HelpName = "seconds", Description = "Stop after this many seconds (default: until Ctrl+C)" };
        var model = ModelOption.Create();
        var ppi = new Option<bool>("--ppi")
        {
            Description = "No handler: the CPUs run an empty program and their ports speak PPI, the S7-200's own protocol, at PPI address = "
                + "station, 9600 (default), 19200 or 187500 baud, 8 data bits, even parity (docs/ppi.md). Without --ppi the ports still "
                + "speak PPI whenever the handler does not hold them in Freeport (STOP, switch at TERM)",
        };
        var command = new Command("simulate", "Serve simulated S7-200 PLCs running the protocol handler on a serial device. Exit codes: 0 stopped, 1 bad input, 2 port failure")
        {
            project, cpu, revision, stations, noProcess, duration, model, ppi,
        };
        serial.AddTo(command);
        handler.AddTo(command);
        command.SetAction(async parse =>
        {
            var cli = context(parse);
            List<ProjectStation>? fromProject = null;
            if (parse.GetValue(project) is { } path)
            {
                var loaded = ProjectFile.Load(path);
                if (!loaded.Ok)
                {
                    return ProjectProblemsView.Report(cli, path, loaded, "nothing simulated");
                }

                if (!SimulatedStations.TrySelect(loaded.Project, path, parse.GetValue(stations) ?? [], out fromProject, out var notOneBus))
                {
                    return cli.Fail(ExitCodes.BadInput, notOneBus);
                }
            }

            var speaksPpi = parse.GetValue(ppi);
            if (speaksPpi && parse.GetValue(model) == SimulationModel.Reference)
            {
                return cli.Fail(ExitCodes.BadInput, "--ppi needs the STL model (the reference model has no PPI side): leave out --model reference");
            }

            if (!SimulatedStations.TryBuild(parse, fromProject, cpu, revision, stations, serial, handler, speaksPpi, out var configs, out var settings, out var error))
            {
                return cli.Fail(ExitCodes.BadInput, error);
            }

            var seconds = parse.GetValue(duration);
            if (seconds is <= 0)
            {
                return cli.Fail(ExitCodes.BadInput, "--duration must be a positive number of seconds");
            }

            var mode = speaksPpi ? PpiMode.WithoutHandler : PpiMode.BesideHandler;
            if (!SimulatedLine.TryCreate(configs, parse.GetValue(model), settings, !parse.GetValue(noProcess), mode, out var line, out error))
            {
                return cli.Fail(ExitCodes.BadInput, error);
            }

            return await ServeAsync(cli, line, settings, configs, seconds is { } s ? TimeSpan.FromSeconds(s) : null, parse.GetValue(model), speaksPpi);
        });
        return command;
    }

    private static async Task<int> ServeAsync(
        CliContext cli, SimulatedLine line, SerialSettings settings, List<HandlerConfig> configs, TimeSpan? duration, SimulationModel model, bool ppi)
    {
        var serving = new SimulationView(configs, settings, line.RunsProcess, model.ToString().ToLowerInvariant()) { Ppi = ppi };
        serving.WriteStart(cli);
        await using var port = new SerialPortTransport(settings);
        var host = line.HostOn(port, TimeProvider.System, cli.Log);
        using var stop = new StopSignals(duration);
        try
        {
            await host.RunAsync(stop.Token);
        }
        catch (OperationCanceledException) when (stop.Token.IsCancellationRequested)
        {
            // Ctrl+C, SIGTERM or the duration: the normal end of a simulation.
        }
        catch (PlcCommunicationException ex)
        {
            return cli.Fail(ExitCodes.LinkFailure, $"{ex.Message}; the simulated PLCs stopped");
        }

        serving.WriteSummary(cli, host.Replies, line.Line.FramesReceived, (line.Line as StlLine)?.PpiFramesAnswered ?? 0);
        return ExitCodes.Ok;
    }
}
