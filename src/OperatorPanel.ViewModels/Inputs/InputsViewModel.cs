using System.Collections.ObjectModel;
using OperatorPanel.ViewModels.Session;
using OperatorPanel.ViewModels.Shell;

namespace OperatorPanel.ViewModels.Inputs;

/// <summary>The Inputs window: every input the project symbolises, as lamps grouped by byte (seed 000 §7, "Input" window).</summary>
public sealed class InputsViewModel : PaneViewModel
{
    private readonly IoPointMap<LampViewModel> _map;

    public InputsViewModel(PanelSession session)
        : base("Inputs", "inputs")
    {
        ArgumentNullException.ThrowIfNull(session);
        _map = new IoPointMap<LampViewModel>(session, s => s.Inputs, (station, symbol) => new LampViewModel(station, symbol));
        session.ProjectChanged += (_, e) =>
        {
            if (e.Kind != ProjectChangeKind.Saved)
            {
                _map.Rebuild();
            }
        };
        _map.Rebuild();
    }

    public ObservableCollection<IoByteGroup<LampViewModel>> Groups => _map.Groups;
}
