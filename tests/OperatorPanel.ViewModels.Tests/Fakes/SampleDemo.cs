using OperatorPanel.Core.Line;
using OperatorPanel.ViewModels.Session;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>The repository's sample project on the test's simulated line, as the App's demo puts it on the simulator.</summary>
internal sealed class SampleDemo(ILineConnector connector) : IDemoSource
{
    public string SampleProjectPath { get; } = Path.Combine(RepositoryRoot(), "samples", "bottling-line.opproj");

    public ILineConnector Connector { get; } = connector;

    private static string RepositoryRoot()
    {
        var folder = new DirectoryInfo(AppContext.BaseDirectory);
        while (folder is not null && !File.Exists(Path.Combine(folder.FullName, "OperatorPanel.sln")))
        {
            folder = folder.Parent;
        }

        return folder?.FullName ?? throw new InvalidOperationException("OperatorPanel.sln not found above " + AppContext.BaseDirectory);
    }
}
