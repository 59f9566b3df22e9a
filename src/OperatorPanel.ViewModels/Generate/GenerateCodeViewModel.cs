using System.Globalization;
using System.Runtime.CompilerServices;
using CommunityToolkit.Mvvm.ComponentModel;
using OperatorPanel.Core.Projects;
using OperatorPanel.StlGen.Options;
using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.ViewModels.Generate;

/// <summary>
/// Generate PLC code (issue 5): the handler settings for one station of the project, prefilled with the generator's
/// defaults for its CPU (HandlerDefaults: buffer at the top of V, the last SBR and INTs). The serial settings come from
/// the station's link, so the handler and the panel always agree on baud, parity and data bits. Any change makes the
/// last result stale: Save needs a fresh Generate.
/// </summary>
public sealed partial class GenerateCodeViewModel : ObservableObject
{
    private readonly PanelProject _project;
    private readonly IFileDialogService _files;
    private int _stationIndex = -1;
    private int _port;
    private string _bufferStart = string.Empty;
    private string _firstSubroutine = string.Empty;
    private string _firstInterrupt = string.Empty;
    private string _charTimeout = string.Empty;
    private bool _writeQ;
    private bool _writeM;
    private bool _writeV;

    public GenerateCodeViewModel(PanelProject project, int stationIndex, IFileDialogService files)
    {
        ArgumentNullException.ThrowIfNull(project);
        ArgumentNullException.ThrowIfNull(files);
        ArgumentOutOfRangeException.ThrowIfNegative(stationIndex);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(stationIndex, project.Stations.Length);
        (_project, _files) = (project, files);
        StationNames = [.. project.Stations.Select(s => string.Create(CultureInfo.InvariantCulture, $"{s.Name} (station {s.Address.Address}, {s.Cpu.DisplayName})"))];
        StationIndex = stationIndex;
    }

    /// <summary>"Filler (station 2, CPU 224)", in project order.</summary>
    public IReadOnlyList<string> StationNames { get; }

    /// <summary>Choosing another station puts that CPU's defaults back in every field.</summary>
    public int StationIndex
    {
        get => _stationIndex;
        set
        {
            if (value >= 0 && value < _project.Stations.Length && SetProperty(ref _stationIndex, value))
            {
                ApplyDefaults();
            }
        }
    }

    public ProjectStation Station => _project.Stations[StationIndex];

    /// <summary>The PLC ports of the station's CPU: [0], or [0, 1] on CPU 224XP and 226.</summary>
    public IReadOnlyList<int> Ports { get; private set; } = [0];

    public int Port { get => _port; set => Change(ref _port, value); }

    /// <summary>The handler's first V byte, "VB7920"; the CPU's default is filled in.</summary>
    public string BufferStart { get => _bufferStart; set => Change(ref _bufferStart, value); }

    public string FirstSubroutine { get => _firstSubroutine; set => Change(ref _firstSubroutine, value); }

    /// <summary>The first of the three interrupt routines.</summary>
    public string FirstInterrupt { get => _firstInterrupt; set => Change(ref _firstInterrupt, value); }

    /// <summary>END_TIMEOUT_MS: the receive ends this long after a request's last character (SMW92); 0 = the default for the baud rate.</summary>
    public string CharTimeout { get => _charTimeout; set => Change(ref _charTimeout, value); }

    public bool WriteQ { get => _writeQ; set => Change(ref _writeQ, value); }

    public bool WriteM { get => _writeM; set => Change(ref _writeM, value); }

    public bool WriteV { get => _writeV; set => Change(ref _writeV, value); }

    /// <summary>Whether the handler gets 08 STOP: the station's "allowStop" in the project decides (File > Edit project).</summary>
    public string StopText => CompactStop.Contradicts(Station.Compact, Station.AllowStop)
        ? "allowed, but the station's handler is compact, which has none: Generate refuses (STL031); clear one of the two in File > Edit project"
        : Station.AllowStop
        ? "included: the project allows the panel to put this CPU into STOP"
        : "not included (allow remote STOP for the station in File > Edit project)";

    /// <summary>The serial settings taken from the station's link: "9600 8N1".</summary>
    public string LineText => Station.Link.LineText;

    private void ApplyDefaults()
    {
        var cpu = Station.Cpu;
        Ports = [.. Enumerable.Range(0, cpu.CommunicationPorts)];
        _port = 0;
        // V_FIRST of the project's protocol 3 handler: where the station's "handlerVFirst" says, else the top of V.
        _bufferStart = string.Create(CultureInfo.InvariantCulture, $"VB{Station.HandlerVFirst ?? HandlerDefaults.V3First(cpu, Station.Compact)}");
        _firstSubroutine = HandlerDefaults.FirstSubroutine(cpu).ToString(CultureInfo.InvariantCulture);
        _firstInterrupt = HandlerDefaults.FirstInterrupt(cpu).ToString(CultureInfo.InvariantCulture);
        var defaults = new HandlerOptions { Cpu = cpu };
        _charTimeout = defaults.CharTimeoutMs.ToString(CultureInfo.InvariantCulture);
        (_writeQ, _writeM, _writeV) = (Writable(2), Writable(3), Writable(4));
        OnPropertyChanged(string.Empty);
        ClearResult();

        static bool Writable(int areaCode) => (HandlerDefaults.WriteMask & (1 << areaCode)) != 0;
    }

    private void Change<T>(ref T field, T value, [CallerMemberName] string? propertyName = null)
    {
        if (SetProperty(ref field, value, propertyName))
        {
            ClearResult();
        }
    }
}
