using System.IO;
using OperatorPanel.ViewModels.Session;
using Serilog;

namespace OperatorPanel.App.Services;

/// <summary>The sample project installed beside the program, on the simulated line.</summary>
public sealed class DemoSource(ILogger log) : IDemoSource
{
    public string SampleProjectPath { get; } = Path.Combine(AppContext.BaseDirectory, "samples", "bottling-line.opproj");

    public ILineConnector Connector { get; } = new DemoLineConnector(log);
}
