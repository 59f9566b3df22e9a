using OperatorPanel.Core.Projects;
using OperatorPanel.Simulator.Hosting;
using Serilog.Core;

namespace OperatorPanel.Demo.Tests;

/// <summary>The demo line both front ends open: one simulated bus per port of the project, with the host's reply allowance.</summary>
public sealed class DemoLineConnectorTests
{
    [Fact]
    public async Task Connect_SampleProject_GivesEveryPortATransportAndTheHostAllowance()
    {
        var project = SampleProject();
        var connector = new DemoLineConnector(SimulationModel.Stl, Logger.None);

        var connection = await connector.ConnectAsync(project, CancellationToken.None);
        var transports = project.Stations.Select(s => connection.TransportFor(s.Link.PortName)).ToList();
        await connection.DisposeAsync();
        foreach (var transport in transports)
        {
            await transport.DisposeAsync();
        }

        connection.ScanAllowance.Should().Be(DemoLine.HostAllowance, "the App's demo and opanel --demo wait the same for a simulated PLC");
        DemoLine.HostAllowance.Should().Be(TimeSpan.FromSeconds(1));
        transports.Select(t => t.Name).Should().Equal(project.Stations.Select(s => $"{s.Link.PortName} (demo)"));
    }

    [Fact]
    public async Task Connect_StationTheGeneratorRefuses_FailsNamingItAndStartsNothing()
    {
        var project = SampleProject();
        var station = project.Stations[0];
        var early = Core.Cpu.CpuProfiles.For(Core.Cpu.CpuModel.Cpu224, Core.Cpu.CpuRevision.Early);
        var refused = project with { Stations = [station with { Cpu = early, Link = station.Link with { BaudRate = 115200 } }] };

        var connect = () => new DemoLineConnector(SimulationModel.Stl, Logger.None).ConnectAsync(refused, CancellationToken.None);

        (await connect.Should().ThrowAsync<InvalidOperationException>()).Which.Message.Should().StartWith($"station {station.Address.Address}: the handler cannot be generated: STL");
    }

    private static PanelProject SampleProject()
    {
        var folder = new DirectoryInfo(AppContext.BaseDirectory);
        while (folder is not null && !File.Exists(Path.Combine(folder.FullName, "OperatorPanel.sln")))
        {
            folder = folder.Parent;
        }

        var load = ProjectFile.Load(Path.Combine(folder!.FullName, "samples", "bottling-line.opproj"));
        load.Ok.Should().BeTrue();
        return load.Project!;
    }
}
