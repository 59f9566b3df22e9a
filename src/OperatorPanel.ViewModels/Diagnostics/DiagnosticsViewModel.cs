using System.Collections.ObjectModel;
using System.Collections.Specialized;
using System.ComponentModel;
using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.ViewModels.Services;
using OperatorPanel.ViewModels.Session;

namespace OperatorPanel.ViewModels.Diagnostics;

/// <summary>The Diagnostics window: per station the identified CPU vs the project's, RUN/STOP, scan times, link statistics.</summary>
public sealed partial class DiagnosticsViewModel : ObservableObject
{
    private readonly PanelSession _session;
    private readonly IDialogService _dialogs;

    public DiagnosticsViewModel(PanelSession session, IDialogService dialogs)
    {
        ArgumentNullException.ThrowIfNull(session);
        ArgumentNullException.ThrowIfNull(dialogs);
        _session = session;
        _dialogs = dialogs;
        session.Stations.CollectionChanged += OnStationsChanged;
        session.PropertyChanged += OnSessionChanged;
        OnStationsChanged(null, new NotifyCollectionChangedEventArgs(NotifyCollectionChangedAction.Reset));
    }

    public ObservableCollection<StationDiagnosticsViewModel> Stations { get; } = [];

    /// <summary>IdentifyCommand: asks every station for IDENTIFY again (after a download, a CPU swap, or a station that came back).</summary>
    [RelayCommand(CanExecute = nameof(IsConnected))]
    private async Task IdentifyAsync()
    {
        try
        {
            await _session.IdentifyAsync();
        }
        catch (Exception exception) when (exception is not OutOfMemoryException)
        {
            _session.StatusLine.ShowError($"IDENTIFY failed: {exception.Message}");
        }
    }

    private bool IsConnected() => _session.IsConnected;

    private void OnStationsChanged(object? sender, NotifyCollectionChangedEventArgs e)
    {
        Stations.Clear();
        foreach (var station in _session.Stations)
        {
            Stations.Add(new StationDiagnosticsViewModel(station, _session, _dialogs));
        }
    }

    private void OnSessionChanged(object? sender, PropertyChangedEventArgs e)
    {
        if (e.PropertyName == nameof(PanelSession.IsConnected))
        {
            IdentifyCommand.NotifyCanExecuteChanged();
        }

        if (e.PropertyName is nameof(PanelSession.IsConnected) or nameof(PanelSession.IsReadOnly))
        {
            foreach (var station in Stations)
            {
                station.OnSessionChanged();
            }
        }
    }
}
