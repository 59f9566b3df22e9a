using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Historian.Recording;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Cli.Bench.History;

/// <summary>
/// The demo bottling line of the sample project on simulated time: the reference PLC running the demo process (the same
/// model <c>watch --demo --model reference</c> serves), every recorded value read from its memory every 100 ms, the
/// project's shortest refresh period, so as many changes as the panel could ever see of it.
/// </summary>
internal sealed class DemoLineStream : IHistoryStream
{
    private readonly List<(ReferencePlc Plc, DemoProcess Process)> _plcs = [];
    private readonly IReadOnlyList<RecordedTag> _tags;
    private TimeSpan _run;

    public DemoLineStream(PanelProject project)
    {
        Project = project;
        _tags = RecordedTag.Of(project);
        foreach (var station in project.Stations)
        {
            var plc = new ReferencePlc(new HandlerConfig(station.Address, station.Cpu));
            _plcs.Add((plc, new DemoProcess(plc)));
        }
    }

    public string Name => "demo line";

    public PanelProject Project { get; }

    public TimeSpan Step => TimeSpan.FromMilliseconds(100);

    public void Publish(BenchLineValues line, TimeSpan elapsed, DateTimeOffset at)
    {
        foreach (var (_, process) in _plcs)
        {
            process.Advance(elapsed - _run);
        }

        _run = elapsed;
        foreach (var tag in _tags)
        {
            var plc = _plcs.First(p => p.Plc.Config.Station == tag.Station).Plc;
            line.Publish(tag.Station, tag.Address, PolledValue.Good(Read(plc.Memory, tag.Address), at));
        }
    }

    private static ImmutableArray<byte> Read(PlcMemory memory, PlcAddress address)
    {
        var bytes = memory.Area(ProtocolAreaExtensions.FromMemoryArea(address.Area)!.Value);
        return address.Bit is { } bit
            ? [(byte)((bytes[address.ByteOffset] >> bit) & 1)]
            : [.. bytes.AsSpan(address.ByteOffset, address.Width.ByteCount())];
    }
}
