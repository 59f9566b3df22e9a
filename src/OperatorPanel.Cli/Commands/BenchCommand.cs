using System.CommandLine;
using OperatorPanel.Cli.Bench;
using OperatorPanel.Cli.Bench.V3;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// <c>opanel bench link [--radio] [--scan-ms M] [--air-baud B] [--cycles N]</c>, <c>opanel bench link --protocol 3 [--radio]</c>,
/// <c>opanel bench link --ppi [--baud 9600|19200|187500]</c>
/// (and <c>bench stl</c>, <c>bench plan</c>, <c>bench history</c>):
/// the characters of a full refresh of the reference line against one item per request and the hex bound, the
/// MODELLED time of a steady and an idle refresh on the PC/PPI cable or (--radio) the radio modules, the targets
/// judged met or NOT MET, then the round trip MEASURED over a socat pty; the text ends with one summary line.
/// Exit 0 when both parts ran (a goal not met is a finding, printed, not an error); 1 when socat is missing or an
/// option is bad; 2 when the measured run failed or no frame got a reply (lost frames are counted in the output).
/// </summary>
internal static class BenchCommand
{
    public const string SocatMissing = "socat not found: measured round trip skipped";

    /// <summary>The reference line's setting: the handler's usual 9600 8N1 (docs/protocol.md section 6).</summary>
    private static readonly LineSetting Setting = LineSetting.Modeled[0];

    /// <summary>Refreshes the PPI bench simulates back to back: enough for the scan's phase to take many values.</summary>
    private const int PpiRefreshes = 40;

    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var command = new Command("bench", "Print figures about the panel's link and planner (modelled and measured)");
        command.Subcommands.Add(CreateLink(context));
        command.Subcommands.Add(StlBenchCommand.Create(context));
        command.Subcommands.Add(PlanBenchCommand.Create(context));
        command.Subcommands.Add(HistoryBenchCommand.Create(context));
        return command;
    }

    private static Command CreateLink(Func<ParseResult, CliContext> context)
    {
        var cycles = new Option<int>("--cycles") { Description = "Full refreshes for the measured round trip (default 50)", DefaultValueFactory = _ => 50 };
        var radio = new Option<bool>("--radio") { Description = "Model the 433 MHz radio module pair instead of the PC/PPI cable" };
        var scan = new Option<double>("--scan-ms")
        {
            Description = "The user program's own time per scan in ms (default 5)",
            DefaultValueFactory = _ => 5,
        };
        var air = new Option<int>("--air-baud")
        {
            Description = "The radio modules' air data rate in baud (default 38400, an assumption)",
            DefaultValueFactory = _ => (int)RadioModuleTiming.Default.AirBaud,
        };
        var ppi = new Option<bool>("--ppi")
        {
            Description = "The reference line read over PPI with no handler (simulated CPU, the panel's PPI master); with --baud",
        };
        var baud = new Option<int>("--baud") { Description = "With --ppi: 9600 (default), 19200 or 187500", DefaultValueFactory = _ => 9600 };
        var usbLatency = new Option<double>("--usb-latency-ms")
        {
            Description = "With --ppi at 187500 baud: the USB-RS485 adapter's latency timer in ms (default 16, FTDI's default)",
            DefaultValueFactory = _ => 16,
        };
        var protocol = new Option<int>("--protocol")
        {
            Description = "Freeport protocol version: 3 (binary frames, docs/protocol.md; default: modelled from the generated handler run in "
                + "the interpreter) or 2 (the former hex frames, for comparison; modelled and measured over a socat pty)",
            DefaultValueFactory = _ => 3,
        };
        var command = new Command("link", "Characters, modelled refresh time (cable, --radio or --ppi) and targets of the reference line; measured round trip")
        {
            cycles, radio, scan, air, ppi, baud, usbLatency, protocol,
        };
        command.SetAction(async (parse, cancellationToken) =>
        {
            var cli = context(parse);
            var count = parse.GetValue(cycles);
            if (count < 1)
            {
                return cli.Fail(ExitCodes.BadInput, $"--cycles {count}: give at least 1 refresh");
            }

            var scanMs = parse.GetValue(scan);
            if (!(scanMs >= 0 && scanMs <= 500))
            {
                return cli.Fail(ExitCodes.BadInput, $"--scan-ms {scanMs}: give 0-500 ms (the S7-200 watchdog ends a scan at 500 ms)");
            }

            var airBaud = parse.GetValue(air);
            if (airBaud is < 600 or > 500_000)
            {
                return cli.Fail(ExitCodes.BadInput, $"--air-baud {airBaud}: the CC1100 runs at 600-500000 baud");
            }

            var version = parse.GetValue(protocol);
            if (version is not (2 or 3))
            {
                return cli.Fail(ExitCodes.BadInput, $"--protocol {version}: give 2 or 3");
            }

            if (parse.GetValue(ppi))
            {
                return parse.GetResult(protocol) is { Implicit: false }
                    ? cli.Fail(ExitCodes.BadInput, $"--protocol {version} and --ppi: PPI is the CPU's own protocol, not a Freeport version; leave out one")
                    : await RunPpiAsync(cli, parse.GetValue(baud), scanMs, parse.GetValue(usbLatency), parse.GetValue(radio));
            }

            if (version == 3)
            {
                return RunV3(cli, Model(parse.GetValue(radio), scanMs, airBaud));
            }

            var line = ReferenceLine.Create();
            var report = LinkBenchReport.Create(line, Model(parse.GetValue(radio), scanMs, airBaud));
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
                    cli.Out.WriteLine(report.Time.SummaryLine);
                }

                return cli.Fail(ExitCodes.LinkFailure, $"measured round trip failed: {exception.Message}");
            }

            Print(cli, report, measured);
            cli.Log.Information("{Summary}", report.Time.SummaryLine);
            return measured is null ? ExitCodes.BadInput
                : measured.FramesFailed == measured.Cycles * measured.FramesPerRefresh ? ExitCodes.LinkFailure
                : ExitCodes.Ok;
        });
        return command;
    }

    /// <summary><c>bench link --protocol 3</c>: the reference line's v3 refresh (<see cref="V3LinkReport"/>); modelled only.</summary>
    private static int RunV3(CliContext cli, LinkTimeModel model)
    {
        if (!V3LinkReport.TryCreate(ReferenceLine.Create(), model, out var report, out var error))
        {
            return cli.Fail(ExitCodes.LinkFailure, $"the v3 handler could not be run: {error}");
        }

        if (cli.Json)
        {
            cli.WriteJson(new
            {
                protocol = 3,
                medium = report.Medium,
                scanMs = model.ProgramScanMs,
                steadyBytes = report.Steady.Chars,
                steadyMs = Math.Round(report.Steady.TotalMs, 1),
                idleBytes = report.Idle.Chars,
                idleMs = Math.Round(report.Idle.TotalMs, 1),
                binaryBoundMs = Math.Round(report.BinaryBoundMs, 1),
                steadyFloorMs = Math.Round(report.Floors.Steady.TotalMs, 1),
                idleFloorMs = Math.Round(report.Floors.Idle.TotalMs, 1),
                notes = report.Problems,
                summary = report.SummaryLine,
            });
        }
        else
        {
            V3LinkText.Write(cli.Out, report);
            cli.Out.WriteLine();
            cli.Out.WriteLine(report.SummaryLine);
        }

        cli.Log.Information("{Summary}", report.SummaryLine);
        return ExitCodes.Ok;
    }

    /// <summary><c>bench link --ppi</c>: the reference line over PPI (<see cref="PpiBench"/>); modelled only, no pty part.</summary>
    private static async Task<int> RunPpiAsync(CliContext cli, int baud, double scanMs, double usbLatencyMs, bool radio)
    {
        if (radio)
        {
            return cli.Fail(ExitCodes.BadInput, "--ppi and --radio: the radio modules carry Freeport frames ('<' ... '>'), not PPI");
        }

        if (baud is not (9600 or 19200 or 187500))
        {
            return cli.Fail(ExitCodes.BadInput, $"--baud {baud}: PPI runs at 9600, 19200 or 187500");
        }

        if (!(usbLatencyMs >= 1 && usbLatencyMs <= 255))
        {
            return cli.Fail(ExitCodes.BadInput, $"--usb-latency-ms {usbLatencyMs}: an FT232R's latency timer is 1-255 ms");
        }

        var report = await PpiBench.RunAsync(ReferenceLine.Create(), baud, scanMs, PpiRefreshes, usbLatencyMs);
        if (cli.Json)
        {
            cli.WriteJson(new
            {
                link = "ppi",
                baud,
                scanMs,
                pcSide = report.Pc.Name,
                jobs = report.Plan.Requests.Length,
                steadyChars = report.SteadyChars,
                steadyMs = Math.Round(report.SteadyMs, 1),
                hexBoundMs = Math.Round(report.HexBoundMs, 1),
                summary = report.SummaryLine,
            });
        }
        else
        {
            PpiBenchText.Write(cli.Out, report);
        }

        cli.Log.Information("{Summary}", report.SummaryLine);
        return ExitCodes.Ok;
    }

    /// <summary>The time model for the chosen medium, with the gap the panel's link keeps on it (LinkOptions).</summary>
    private static LinkTimeModel Model(bool radio, double scanMs, int airBaud)
    {
        var serial = new SerialSettings { PortName = "bench", BaudRate = Setting.Baud, Kind = radio ? LinkKind.RadioModule : LinkKind.Cable };
        var options = LinkOptions.For(serial);
        return new LinkTimeModel(
            Setting,
            options.ReplyDelay.TotalMilliseconds,
            scanMs,
            options.InterFrameGap.TotalMilliseconds,
            radio ? RadioModuleTiming.Default with { AirBaud = airBaud } : null);
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

        cli.Out.WriteLine();
        cli.Out.WriteLine(report.Time.SummaryLine);
    }
}
