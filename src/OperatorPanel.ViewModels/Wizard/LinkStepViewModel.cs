using System.Collections.ObjectModel;
using System.Globalization;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>
/// Step 5: the link (seed 000 §5-6): a serial port from those present (or typed, for a PC where it is not plugged in),
/// Freeport (our handler) or PPI (no program of ours, docs/ppi.md section 14), the line settings the CPU can run for it
/// (Freeport: seed 002 Table C-11; PPI: 9600, 19200 or 187500 baud, 8E1), cable or radio module, and "test connection".
/// </summary>
public sealed partial class LinkStepViewModel : WizardStepViewModel
{
    /// <summary>The wizard's words for the two settings: its check boxes.</summary>
    private static readonly CompactStopWords StopWords = new(
        "\"Compact handler\" ticked", "\"Allow remote STOP\" ticked on step 1", "clear \"Compact handler\"", "clear \"Allow remote STOP\" on step 1");

    private readonly CpuStepViewModel _cpuStep;
    private readonly ISerialPortCatalog _catalog;
    private readonly IConnectionTester _tester;
    private readonly TimeProvider _time;
    private string _portName;
    private int _baudRate;
    private Parity _parity;
    private int _dataBits;
    private LinkKind _kind;
    private LinkProtocol _protocol;
    private bool _compact;

    internal LinkStepViewModel(SerialSettings link, bool compact, CpuStepViewModel cpuStep, ISerialPortCatalog catalog, IConnectionTester tester, TimeProvider time)
    {
        (_cpuStep, _catalog, _tester, _time) = (cpuStep, catalog, tester, time);
        (_portName, _baudRate, _parity, _dataBits, _kind, _protocol, _compact) = (link.PortName, link.BaudRate, link.Parity, link.DataBits, link.Kind, link.Protocol, compact);
        cpuStep.PropertyChanged += (_, e) =>
        {
            if (e.PropertyName == nameof(CpuStepViewModel.Cpu))
            {
                OnPropertyChanged(nameof(BaudRates));
                Compact = _cpuStep.Cpu.OffersCompactHandler;
            }
        };
        RefreshPorts();
    }

    public override int Number => 5;

    public override string Title => "Link";

    public ObservableCollection<PortChoice> Ports { get; } = [];

    /// <summary>The Freeport rates of the chosen CPU, slowest first; over PPI the PPI rates.</summary>
    public IReadOnlyList<int> BaudRates => Protocol == LinkProtocol.Ppi ? PpiRates : [.. _cpuStep.Cpu.FreeportBaudRates.Select(r => r.Baud).Order()];

    /// <summary>The S7-200's PPI rates (seed 002, Tables ).</summary>
    public static IReadOnlyList<int> PpiRates { get; } = [9600, 19200, 187500];

    public IReadOnlyList<LinkProtocol> Protocols { get; } = Enum.GetValues<LinkProtocol>();

    /// <summary>The trade-off between the two, in one sentence for the step's page.</summary>
    public static string ProtocolHint =>
        "Freeport needs our handler in the PLC and gives change-only refresh and the radio modules; PPI needs no program "
        + "in the PLC and works in STOP, but reads every value each refresh, runs at 9.6 or 19.2 kbaud on the PC/PPI cable "
        + "(187.5 on a USB-RS485 adapter) and needs the panel to be the only master on the bus.";

    /// <summary>Freeport or PPI; choosing PPI sets its fixed character (8 data bits, even parity), a PPI rate and the cable.</summary>
    public LinkProtocol Protocol
    {
        get => _protocol;
        set
        {
            if (_protocol == value)
            {
                return;
            }

            Edit(ref _protocol, value);
            if (value == LinkProtocol.Ppi)
            {
                (Parity, DataBits, Kind) = (Parity.Even, 8, LinkKind.Cable);
                BaudRate = PpiRates.Contains(BaudRate) ? BaudRate : PpiRates[0];
            }

            OnPropertyChanged(nameof(BaudRates));
            OnPropertyChanged(nameof(CanBeCompact));
        }
    }

    /// <summary>Why the compact handler is offered first for a CPU 221 or 222, in one sentence for the step's page.</summary>
    public static string CompactHint =>
        "The compact handler (read and write only: no change-only list, no remote STOP) needs 178 V bytes and about half the "
        + "program of the full one, so it is the default for a CPU 221 or 222, whose 4096 bytes of program memory the full "
        + "handler would crowd; the panel then reads 16 bytes per request instead of the whole list in one.";

    /// <summary>
    /// The station's handler is the compact protocol 3 one (ProjectStation.Compact); set when the CPU step chooses a CPU
    /// 221 or 222, cleared for the larger CPUs, and the user may change it. Freeport only.
    /// </summary>
    public bool Compact { get => _compact; set => Edit(ref _compact, value); }

    /// <summary>A handler only runs on a Freeport bus.</summary>
    public bool CanBeCompact => Protocol == LinkProtocol.Freeport;

    public IReadOnlyList<Parity> Parities { get; } = Enum.GetValues<Parity>();

    /// <summary>SMB30 bit 5: 8 or 7 data bits per character.</summary>
    public IReadOnlyList<int> DataBitChoices { get; } = [8, 7];

    public IReadOnlyList<LinkKind> Kinds { get; } = Enum.GetValues<LinkKind>();

    public string PortName
    {
        get => _portName;
        set
        {
            Edit(ref _portName, value ?? string.Empty);
            OnPropertyChanged(nameof(IsFtdiPort));
        }
    }

    /// <summary>True when the chosen port is an FTDI device, as the radio module is.</summary>
    public bool IsFtdiPort => Ports.Any(p => p.IsFtdi && string.Equals(p.PortName, PortName.Trim(), StringComparison.OrdinalIgnoreCase));

    public int BaudRate { get => _baudRate; set => Edit(ref _baudRate, value); }

    public Parity Parity { get => _parity; set => Edit(ref _parity, value); }

    public int DataBits { get => _dataBits; set => Edit(ref _dataBits, value); }

    public LinkKind Kind { get => _kind; set => Edit(ref _kind, value); }

    internal SerialSettings Build() => new()
    {
        PortName = PortName.Trim(),
        BaudRate = BaudRate,
        Parity = Parity,
        DataBits = DataBits,
        StopBits = 1,
        Kind = Kind,
        Protocol = Protocol,
    };

    internal override IEnumerable<string> Check(WizardContext context)
    {
        if (string.IsNullOrWhiteSpace(PortName))
        {
            yield return "Choose a serial port, or type one such as COM3 or /dev/ttyUSB0.";
        }
        else if (WizardText.Check(TextRule.Port, PortName) is { } port)
        {
            yield return WizardText.Sentence(port);
        }

        if (Protocol == LinkProtocol.Ppi)
        {
            foreach (var problem in CheckPpi())
            {
                yield return problem;
            }

            yield break;
        }

        if (context.Cpu.FreeportBaudCode(BaudRate) is null)
        {
            var rates = string.Join(", ", BaudRates.Select(b => b.ToString(CultureInfo.InvariantCulture)));
            yield return string.Create(CultureInfo.InvariantCulture, $"{context.Cpu.DisplayName} cannot run Freeport at {BaudRate} baud; use one of {rates}.");
        }

        if (DataBits is not (7 or 8))
        {
            yield return string.Create(CultureInfo.InvariantCulture, $"{DataBits} data bits: a Freeport character has 7 or 8 (SMB30 bit 5).");
        }

        // Core's rule, as project check and generate apply it: step 1's "Allow remote STOP" and this page's "Compact
        // handler" together would give a handler without STOP. Flagged here, where Finish is, so step 1 stays passable.
        if (CompactStop.Contradicts(Compact, _cpuStep.AllowStop))
        {
            yield return WizardText.Sentence(CompactStop.Describe(StationWho(), StopWords));
        }
    }

    private string StationWho() => _cpuStep.Station is { } station
        ? string.Create(CultureInfo.InvariantCulture, $"{_cpuStep.StationName.Trim()} (station {station.Address})")
        : _cpuStep.StationName.Trim();

    private IEnumerable<string> CheckPpi()
    {
        if (!PpiRates.Contains(BaudRate))
        {
            yield return string.Create(CultureInfo.InvariantCulture, $"PPI runs at 9600, 19200 or 187500 baud, not {BaudRate}.");
        }

        if (Parity != Parity.Even || DataBits != 8)
        {
            yield return "A PPI character is always 8 data bits with even parity.";
        }

        if (Kind != LinkKind.Cable)
        {
            yield return "The radio modules carry the handler's Freeport frames; PPI needs the cable.";
        }
    }

    [RelayCommand]
    private void RefreshPorts()
    {
        Ports.Clear();
        foreach (var port in _catalog.List())
        {
            Ports.Add(new PortChoice(port));
        }

        if (string.IsNullOrWhiteSpace(PortName) && Ports.Count > 0)
        {
            PortName = Ports[0].PortName;
        }

        OnPropertyChanged(nameof(IsFtdiPort));
    }
}
