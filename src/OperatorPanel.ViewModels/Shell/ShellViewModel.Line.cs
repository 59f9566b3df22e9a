using OperatorPanel.Core.Polling;
using OperatorPanel.ViewModels.Mvvm;

namespace OperatorPanel.ViewModels.Shell;

/// <summary>The line: connect, disconnect, refresh mode (F5 refreshes in triggered mode), read-only mode, the demo.</summary>
public sealed partial class ShellViewModel
{
    public AsyncRelayCommand ConnectCommand { get; }

    public AsyncRelayCommand DisconnectCommand { get; }

    /// <summary>F5: one full cycle of every station now.</summary>
    public AsyncRelayCommand RefreshNowCommand { get; }

    /// <summary>Continuous ⇄ triggered (seed 000 §7, the two refresh modes).</summary>
    public RelayCommand ToggleRefreshModeCommand { get; }

    public RelayCommand ToggleReadOnlyCommand { get; }

    /// <summary>Opens the sample project on the simulated line; enabled when the App offers a demo.</summary>
    public AsyncRelayCommand DemoCommand { get; }

    public bool IsConnected => Session.IsConnected;

    public bool IsContinuous
    {
        get => Session.Mode == RefreshMode.Continuous;
        set => Session.Mode = value ? RefreshMode.Continuous : RefreshMode.OnDemand;
    }

    /// <summary>No writes: every switch and editor is disabled, and the session refuses writes as well.</summary>
    public bool IsReadOnly
    {
        get => Session.IsReadOnly;
        set => Session.IsReadOnly = value;
    }

    private (AsyncRelayCommand, AsyncRelayCommand, AsyncRelayCommand, RelayCommand, RelayCommand, AsyncRelayCommand) CreateLineCommands() =>
    (
        new AsyncRelayCommand(ConnectAsync, () => HasProject && !Session.IsConnected),
        new AsyncRelayCommand(DisconnectAsync, () => Session.IsConnected),
        new AsyncRelayCommand(RefreshNowAsync, () => Session.IsConnected),
        new RelayCommand(ToggleRefreshMode),
        new RelayCommand(() => IsReadOnly = !IsReadOnly),
        new AsyncRelayCommand(DemoAsync, () => _services.Demo is not null)
    );

    private async Task ConnectAsync()
    {
        try
        {
            await Session.ConnectAsync(IsDemo && _services.Demo is { } demo ? demo.Connector : _services.Connector);
        }
        catch (Exception exception) when (exception is not OutOfMemoryException)
        {
            _logger.Error(exception, "Connecting failed");
            StatusLine.ShowError($"Not connected: {exception.Message}");
        }
    }

    private async Task DisconnectAsync()
    {
        try
        {
            await Session.DisconnectAsync();
        }
        catch (Exception exception) when (exception is not OutOfMemoryException)
        {
            _logger.Error(exception, "Disconnecting failed");
            StatusLine.ShowError($"Disconnect failed: {exception.Message}");
        }
    }

    private async Task RefreshNowAsync()
    {
        try
        {
            await Session.RefreshNowAsync();
            StatusLine.Show($"Refreshed at {_time.GetLocalNow():HH:mm:ss}");
        }
        catch (OperationCanceledException)
        {
            StatusLine.Show("Refresh cancelled: the line was disconnected");
        }
    }

    private void ToggleRefreshMode()
    {
        IsContinuous = !IsContinuous;
        StatusLine.Show(IsContinuous ? "Refresh: continuous" : "Refresh: triggered; F5 refreshes");
    }

    private async Task DemoAsync()
    {
        if (_services.Demo is not { } demo || !await ConfirmDiscardAsync() || !await LoadAndReplaceAsync(demo.SampleProjectPath, demo: true))
        {
            return;
        }

        await ConnectAsync();
    }
}
