using System.IO;
using OperatorPanel.Core.Line;
using OperatorPanel.Demo;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.ViewModels.Session;
using Serilog;

namespace OperatorPanel.App.Services;

/// <summary>
/// The sample project installed beside the program, on the demo line opanel's <c>--demo</c> uses too: the generated
/// handler in the STL interpreter, with the same warm-up and reply allowance (<see cref="DemoLine"/>).
/// </summary>
public sealed class DemoSource(ILogger log) : IDemoSource
{
    public string SampleProjectPath { get; } = Path.Combine(AppContext.BaseDirectory, "samples", "bottling-line.opproj");

    public ILineConnector Connector { get; } = new DemoLineConnector(SimulationModel.Stl, log);
}
