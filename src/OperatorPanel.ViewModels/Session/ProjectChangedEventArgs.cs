using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Session;

public sealed class ProjectChangedEventArgs(PanelProject project, ProjectChangeKind kind) : EventArgs
{
    public PanelProject Project { get; } = project;

    public ProjectChangeKind Kind { get; } = kind;
}
