using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Shell;

/// <summary>
/// Where File > New gets its project: the project wizard (seed 000 §7, five steps) once it is wired in, or
/// <see cref="StarterProjectSource"/> until then. Null means the operator cancelled.
/// </summary>
public interface INewProjectSource
{
    Task<PanelProject?> CreateAsync();
}
