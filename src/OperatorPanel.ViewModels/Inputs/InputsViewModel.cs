using System.Collections.ObjectModel;
using CommunityToolkit.Mvvm.ComponentModel;
using OperatorPanel.ViewModels.Session;

namespace OperatorPanel.ViewModels.Inputs;

/// <summary>The Inputs window: every input the project symbolises, as lamps grouped by byte (seed 000 §7, "Input" window).</summary>
public sealed class InputsViewModel : ObservableObject
{
    private readonly IoPointMap<LampViewModel> _map;

    public InputsViewModel(PanelSession session)
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
