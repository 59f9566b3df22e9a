using OperatorPanel.Core.Line;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>Hands every connect to <paramref name="inner"/> and keeps the project it was asked to connect.</summary>
internal sealed class RecordingConnector(ILineConnector inner) : ILineConnector
{
    private readonly List<PanelProject> _projects = [];

    public IReadOnlyList<PanelProject> Projects => _projects;

    public Task<LineConnection> ConnectAsync(PanelProject project, CancellationToken cancellationToken)
    {
        _projects.Add(project);
        return inner.ConnectAsync(project, cancellationToken);
    }
}
