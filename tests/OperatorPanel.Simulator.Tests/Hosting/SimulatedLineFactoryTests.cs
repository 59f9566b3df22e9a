using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using static OperatorPanel.Simulator.Tests.Hosting.StlStations;

namespace OperatorPanel.Simulator.Tests.Hosting;

/// <summary>One factory for both models; the STL model runs whatever text the handler source gives (here: StlGen's, embedded).</summary>
public sealed class SimulatedLineFactoryTests
{
    /// <summary>The embedded handlers were generated for 9600 8N1.</summary>
    private static readonly SerialSettings Serial = new() { PortName = "test", BaudRate = 9600 };

    private static readonly HandlerConfig[] Stations = [new(new Station(2), Cpu224) { Protocol = 2 }, new(new Station(3), Cpu224) { Protocol = 2 }];

    [Fact]
    public void TryCreate_StlModel_EachStationRunsTheTextTheSourceGives()
    {
        var asked = new List<int>();

        SimulatedLineFactory.TryCreate(Stations, SimulationModel.Stl, Serial, runProcess: false, Recording(asked), out var line, out var error)
            .Should().BeTrue(error);

        asked.Should().Equal(2, 3);
        var stl = line.Should().BeOfType<StlLine>().Subject;
        stl.Stations.Should().HaveCount(2);
        stl.Processes.Should().BeEmpty();
        stl.RunUntil(TimeSpan.FromMilliseconds(50));
        Decode(Exchange(stl, Identify(3, sequence: 7), TimeSpan.FromMilliseconds(400))).Should().Match<Core.Protocol.FreeportFrame>(f => f.Station == 3 && f.Sequence == 7);
    }

    [Fact]
    public void TryCreate_StlModelWithProcess_RunsADemoProcessPerStation()
    {
        SimulatedLineFactory.TryCreate(Stations, SimulationModel.Stl, Serial, runProcess: true, Recording([]), out var line, out var error)
            .Should().BeTrue(error);

        line.Should().BeOfType<StlLine>().Which.Processes.Should().HaveCount(2);
    }

    [Fact]
    public void TryCreate_ReferenceModel_BuildsReferencePlcsWithoutAskingTheSource()
    {
        var asked = new List<int>();

        SimulatedLineFactory.TryCreate(Stations, SimulationModel.Reference, Serial, runProcess: true, Recording(asked), out var line, out var error)
            .Should().BeTrue(error);

        asked.Should().BeEmpty();
        line.Should().BeOfType<ReferenceLine>().Which.Bus.Ports.Should().HaveCount(2);
    }

    [Fact]
    public void TryCreate_ReferenceModelProtocol3_BuildsV3StationsWithTheirSetupAndProcesses()
    {
        HandlerConfig[] v3 = [new(new Station(2), Cpu224, allowStop: true), new(new Station(3), Cpu224, charTimeoutMs: 9) { Compact = true, V3First = 8000 }];

        SimulatedLineFactory.TryCreate(v3, SimulationModel.Reference, Serial, runProcess: true, Recording([]), out var line, out var error)
            .Should().BeTrue(error);

        var reference = line.Should().BeOfType<V3ReferenceLine>().Subject;
        reference.RunsProcess.Should().BeTrue();
        reference.Stations.Select(s => (s.Setup.Station.Address, s.Setup.Shape.HasList, s.Setup.AllowStop, s.Setup.EndTimeoutMs, s.Setup.WriteMask))
            .Should().Equal((2, true, true, (byte)4, (byte)0x1C), (3, false, false, (byte)9, (byte)0x1C));
        reference.Stations[1].Setup.VFirst.Should().Be(8000);
    }

    [Fact]
    public void TryCreate_ReferenceModelMixedProtocols_FailsSayingOneProtocolPerLine()
    {
        SimulatedLineFactory.TryCreate([Stations[0], new(new Station(4), Cpu224)], SimulationModel.Reference, Serial, runProcess: false, Recording([]), out var line, out var error)
            .Should().BeFalse();

        line.Should().BeNull();
        error.Should().Contain("one protocol per line");
    }

    [Fact]
    public void TryCreate_SourceFails_ReturnsItsReasonNamingTheStation()
    {
        var act = () => SimulatedLineFactory.TryCreate(Stations, SimulationModel.Stl, Serial, runProcess: true, FailsFor(3), out _, out _);
        act.Should().NotThrow();

        SimulatedLineFactory.TryCreate(Stations, SimulationModel.Stl, Serial, runProcess: true, FailsFor(3), out var line, out var error)
            .Should().BeFalse();

        line.Should().BeNull();
        error.Should().Be("station 3: the handler cannot be generated: STL003 no such port");
    }

    [Fact]
    public void TryCreate_SourceTextDoesNotLoad_ReturnsTheLoaderReason()
    {
        SimulatedLineFactory.TryCreate(Stations, SimulationModel.Stl, Serial, runProcess: false, Text("NOT AN STL PROGRAM"), out var line, out var error)
            .Should().BeFalse();

        line.Should().BeNull();
        error.Should().StartWith("station 2: the handler does not load in the interpreter: ").And.Contain("diagnostic");
    }

    private static StlHandlerSource Recording(List<int> asked) =>
        (HandlerConfig station, SerialSettings serial, [NotNullWhen(true)] out string? awl, [NotNullWhen(false)] out string? error) =>
        {
            asked.Add(station.Station.Address);
            using var stream = typeof(StlStations).Assembly.GetManifestResourceStream($"Handler224Station{station.Station.Address}.awl")!;
            using var reader = new StreamReader(stream);
            (awl, error) = (reader.ReadToEnd(), null);
            return true;
        };

    private static StlHandlerSource FailsFor(int failing) =>
        (HandlerConfig station, SerialSettings serial, [NotNullWhen(true)] out string? awl, [NotNullWhen(false)] out string? error) =>
        {
            if (station.Station.Address == failing)
            {
                (awl, error) = (null, "the handler cannot be generated: STL003 no such port");
                return false;
            }

            return Recording([])(station, serial, out awl, out error);
        };

    private static StlHandlerSource Text(string text) =>
        (HandlerConfig station, SerialSettings serial, [NotNullWhen(true)] out string? awl, [NotNullWhen(false)] out string? error) =>
        {
            (awl, error) = (text, null);
            return true;
        };
}
