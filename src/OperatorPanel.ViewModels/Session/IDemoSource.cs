using OperatorPanel.Core.Line;

namespace OperatorPanel.ViewModels.Session;

/// <summary>
/// What the Demo command needs from the App: the sample project shipped with it (samples/bottling-line.opproj) and a
/// connector that puts simulated PLCs running the demo process on every bus of a project.
/// </summary>
public interface IDemoSource
{
    string SampleProjectPath { get; }

    ILineConnector Connector { get; }
}
