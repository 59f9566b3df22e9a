using CommunityToolkit.Mvvm.Input;

namespace OperatorPanel.ViewModels.Shell;

/// <summary>
/// The line: connect, disconnect, refresh mode (F5 refreshes in triggered mode), read-only mode, the demo. The state they
/// switch is the session's (Session.IsConnected, IsContinuous, IsReadOnly), which the window binds to directly.
/// </summary>
public sealed partial class ShellViewModel
{
    [RelayCommand(CanExecute = nameof(CanConnect))]
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

    [RelayCommand(CanExecute = nameof(IsConnected))]
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

    /// <summary>F5 (RefreshNowCommand): one full cycle of every station now.</summary>
    [RelayCommand(CanExecute = nameof(IsConnected))]
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

    /// <summary>Continuous ⇄ triggered (seed 000 §7, the two refresh modes).</summary>
    [RelayCommand]
    private void ToggleRefreshMode()
    {
        Session.IsContinuous = !Session.IsContinuous;
        StatusLine.Show(Session.IsContinuous ? "Refresh: continuous" : "Refresh: triggered; F5 refreshes");
    }

    [RelayCommand]
    private void ToggleReadOnly() => Session.IsReadOnly = !Session.IsReadOnly;

    /// <summary>DemoCommand: opens the sample project on the simulated line; enabled when the App offers a demo.</summary>
    [RelayCommand(CanExecute = nameof(HasDemo))]
    private async Task DemoAsync()
    {
        if (_services.Demo is not { } demo || !await ConfirmDiscardAsync() || !await LoadAndReplaceAsync(demo.SampleProjectPath, demo: true))
        {
            return;
        }

        await ConnectAsync();
    }

    /// <summary>
    /// ReadOverPpiCommand (Line > Read over PPI): offered while a Freeport station's handler is silent (STOP, TERM); its
    /// bus reconnects over PPI, the project file unchanged (PanelSession.ReadOverPpiAsync).
    /// </summary>
    [RelayCommand(CanExecute = nameof(CanReadOverPpi))]
    private Task ReadOverPpiAsync() =>
        Session.SilentFreeportStation is { } station ? RelinkAsync(() => Session.ReadOverPpiAsync(station)) : Task.CompletedTask;

    /// <summary>BackToFreeportCommand: the project's own links again, reconnected.</summary>
    [RelayCommand(CanExecute = nameof(IsReadingOverPpi))]
    private Task BackToFreeportAsync() => RelinkAsync(() => Session.BackToFreeportAsync());

    private async Task RelinkAsync(Func<Task> relink)
    {
        try
        {
            await relink();
        }
        catch (Exception exception) when (exception is not OutOfMemoryException)
        {
            _logger.Error(exception, "Switching the link failed");
            StatusLine.ShowError($"Not connected: {exception.Message}");
        }
    }

    private bool CanReadOverPpi() => Session.SilentFreeportStation is not null;

    private bool IsReadingOverPpi() => Session.IsReadingOverPpi;

    private bool CanConnect() => HasProject && !Session.IsConnected;

    private bool IsConnected() => Session.IsConnected;

    private bool HasDemo() => _services.Demo is not null;
}
