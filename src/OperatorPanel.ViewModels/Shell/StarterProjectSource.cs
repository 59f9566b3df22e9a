using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Shell;

/// <summary>A CPU 224 at station 2 on COM1 with every local input and output symbolised (Core's StarterProject).</summary>
public sealed class StarterProjectSource : INewProjectSource
{
    public Task<PanelProject?> CreateAsync() =>
        Task.FromResult<PanelProject?>(StarterProject.Create("Untitled", CpuProfiles.For(CpuModel.Cpu224), new Station(2), "COM1"));
}
