using System.Collections.ObjectModel;
using System.ComponentModel;
using CommunityToolkit.Mvvm.ComponentModel;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Writes;
using OperatorPanel.ViewModels.Inputs;
using OperatorPanel.ViewModels.Services;
using OperatorPanel.ViewModels.Session;
using Serilog;
using Serilog.Core;

namespace OperatorPanel.ViewModels.Outputs;

/// <summary>
/// The Outputs window: every output the project symbolises, as lamps with a switch (seed 000 §7, "Output" window).
/// A switch writes the bit with WRITE BIT through its bus, which logs it with old and new value.
/// </summary>
public sealed class OutputsViewModel : ObservableObject
{
    private readonly PanelSession _session;
    private readonly IDialogService _dialogs;
    private readonly PanelOptions _options;
    private readonly ILogger _logger;
    private readonly IoPointMap<OutputViewModel> _map;

    public OutputsViewModel(PanelSession session, IDialogService dialogs, PanelOptions options, ILogger? logger = null)
    {
        ArgumentNullException.ThrowIfNull(session);
        ArgumentNullException.ThrowIfNull(dialogs);
        ArgumentNullException.ThrowIfNull(options);
        (_session, _dialogs, _options) = (session, dialogs, options);
        _logger = (logger ?? Logger.None).ForContext<OutputsViewModel>();
        _map = new IoPointMap<OutputViewModel>(session, s => s.Outputs, (station, symbol) => new OutputViewModel(station, symbol, SwitchAsync, CanWrite));
        session.ProjectChanged += (_, e) =>
        {
            if (e.Kind != ProjectChangeKind.Saved)
            {
                _map.Rebuild();
            }
        };
        session.PropertyChanged += OnSessionChanged;
        _map.Rebuild();
    }

    /// <summary>Shown above the lamps: a written output is only as lasting as the PLC program allows.</summary>
    public string OverwriteWarning { get; } = "The PLC program may overwrite an output on its next scan; the lamp shows what the PLC holds.";

    public ObservableCollection<IoByteGroup<OutputViewModel>> Groups => _map.Groups;

    private bool CanWrite() => _session.IsConnected && !_session.IsReadOnly;

    private async Task SwitchAsync(OutputViewModel output)
    {
        var target = output.Value != true;
        var newValue = target ? "1" : "0";
        if (!CanWrite())
        {
            return;
        }

        var current = output.Value is { } now ? (now ? "1" : "0") : null;
        if (_options.ConfirmWrites && !await _dialogs.ConfirmAsync("Switch output", WriteMessages.Question(output.PlcAddress, output.Symbol, current, output.Quality, newValue)))
        {
            return;
        }

        output.WriteError = null;
        output.Writing = target;
        WriteOutcome outcome;
        try
        {
            outcome = await _session.WriteAsync(WriteRequest.Bit(output.Station, output.PlcAddress, target));
        }
        catch (Exception exception) when (exception is not OutOfMemoryException)
        {
            _logger.Error(exception, "Switching {Address} failed in the panel", output.Address);
            outcome = new WriteOutcome.Unknown(default, $"the panel failed: {exception.Message}", "it may have reached the PLC");
        }
        finally
        {
            output.Writing = null;
        }

        output.WriteError = WriteMessages.Problem(output.PlcAddress, DisplayFormat.Bool, outcome);
        var status = WriteMessages.StatusText(output.Symbol, output.PlcAddress, DisplayFormat.Bool, newValue, outcome);
        if (output.WriteError is null)
        {
            _session.StatusLine.Show(status);
        }
        else
        {
            _session.StatusLine.ShowError(status);
        }
    }

    private void OnSessionChanged(object? sender, PropertyChangedEventArgs e)
    {
        if (e.PropertyName is nameof(PanelSession.IsConnected) or nameof(PanelSession.IsReadOnly))
        {
            foreach (var output in _map.Points)
            {
                output.SwitchCommand.NotifyCanExecuteChanged();
            }
        }
    }
}
