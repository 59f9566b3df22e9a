using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.StlGen;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// The interpreter's real-time speed: the CPU 224 handler StlGen generates, on an <see cref="StlLine"/> run as fast as it
/// goes, serving an IDENTIFY, the largest WRITE (255 characters, the frame limit) and the largest READ, each repeated.
/// Simulated time includes the line (characters at the baud rate), the reply delay and the idle scans in between.
/// </summary>
internal static class StlBench
{
    private static readonly Station Station = new(2);
    private static readonly TimeSpan Step = TimeSpan.FromMilliseconds(1);
    private static readonly TimeSpan GiveUp = TimeSpan.FromSeconds(1);

    public static bool TryRun(int baud, int requests, TimeProvider time, out IReadOnlyList<StlBenchResult> results, out string error)
    {
        results = [];
        var cpu = CpuProfiles.For(CpuModel.Cpu224);
        var generated = HandlerGenerator.Generate(new HandlerOptions { Cpu = cpu, Station = Station.Address, BaudRate = baud, Protocol = 2 });
        if (!generated.Ok)
        {
            error = $"the handler cannot be generated: {string.Join("; ", generated.Diagnostics)}";
            return false;
        }

        var settings = new LineSettings(baud, Core.Transport.Parity.None, 8);
        var workloads = new (string Name, byte[] Frame)[]
        {
            ("IDENTIFY", RequestCodec.Encode(new IdentifyRequest(Station, 1))),
            ($"WRITE {ProtocolLimits.MaxWriteData} bytes", RequestCodec.Encode(new WriteBlockRequest(Station, 1, ProtocolArea.V, 0, [.. new byte[ProtocolLimits.MaxWriteData]]))),
            ($"READ {ProtocolLimits.MaxReadData} bytes", RequestCodec.Encode(new ReadRequest(Station, 1, [new ReadItem(ProtocolArea.V, 0, ProtocolLimits.MaxReadData)]))),
        };
        var list = new List<StlBenchResult>();
        foreach (var (name, frame) in workloads)
        {
            if (!StlStation.TryCreate(generated.AwlText, cpu, 0, settings, out var station, out error))
            {
                return false;
            }

            var line = new StlLine(settings);
            line.Attach(station, runProcess: false);
            line.RunUntil(TimeSpan.FromMilliseconds(20));
            list.Add(Measure(line, name, frame, requests, time));
        }

        results = list;
        error = string.Empty;
        return true;
    }

    private static StlBenchResult Measure(StlLine line, string name, byte[] frame, int requests, TimeProvider time)
    {
        var plc = line.Stations[0].Plc;
        var (simulatedStart, instructionsStart, replyChars) = (line.Now, plc.InstructionsExecuted, 0);
        var started = time.GetTimestamp();
        for (var i = 0; i < requests; i++)
        {
            line.Deliver(frame);
            var giveUp = line.Now + GiveUp;
            var answered = line.Replies;
            replyChars = 0;
            while (line.Replies == answered && line.Now < giveUp)
            {
                line.RunUntil(line.Now + Step);
                replyChars += line.TakeCharacters().Count;
            }
        }

        return new StlBenchResult(
            name, frame.Length, replyChars, requests, line.Replies, line.Now - simulatedStart, time.GetElapsedTime(started),
            plc.InstructionsExecuted - instructionsStart);
    }
}
