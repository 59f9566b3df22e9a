using System.Collections.ObjectModel;
using System.Globalization;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>
/// Step 5: the link (seed 000 §5-6): a serial port from those present (or typed, for a PC where it is not plugged in),
/// the Freeport line settings the CPU can run (seed 002, Table C-11), cable or radio module, and "test connection".
/// </summary>
public sealed partial class LinkStepViewModel : WizardStepViewModel
{
    private readonly CpuStepViewModel _cpuStep;
    private readonly ISerialPortCatalog _catalog;
    private readonly IConnectionTester _tester;
    private readonly TimeProvider _time;
    private string _portName;
    private int _baudRate;
    private Parity _parity;
    private int _dataBits;
    private LinkKind _kind;

    internal LinkStepViewModel(SerialSettings link, CpuStepViewModel cpuStep, ISerialPortCatalog catalog, IConnectionTester tester, TimeProvider time)
    {
        (_cpuStep, _catalog, _tester, _time) = (cpuStep, catalog, tester, time);
        (_portName, _baudRate, _parity, _dataBits, _kind) = (link.PortName, link.BaudRate, link.Parity, link.DataBits, link.Kind);
        cpuStep.PropertyChanged += (_, e) =>
        {
            if (e.PropertyName == nameof(CpuStepViewModel.Cpu))
            {
                OnPropertyChanged(nameof(BaudRates));
            }
        };
        RefreshPorts();
    }

    public override int Number => 5;

    public override string Title => "Link";

    public ObservableCollection<PortChoice> Ports { get; } = [];

    /// <summary>The Freeport rates of the chosen CPU, slowest first.</summary>
    public IReadOnlyList<int> BaudRates => [.. _cpuStep.Cpu.FreeportBaudRates.Select(r => r.Baud).Order()];

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
    };

    internal override IEnumerable<string> Check(WizardContext context)
    {
        if (string.IsNullOrWhiteSpace(PortName))
        {
            yield return "Choose a serial port, or type one such as COM3 or /dev/ttyUSB0.";
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
