using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.ViewModels.Mvvm;

namespace OperatorPanel.ViewModels.Inputs;

/// <summary>One symbolised I or Q bit as a lamp: the value shown is always the last one read from the PLC.</summary>
public abstract class IoPointViewModel : ObservableObject
{
    private bool? _value;
    private ValueQuality _quality = ValueQuality.Bad;
    private string? _qualityText = "not read yet";

    protected IoPointViewModel(ProjectStation station, IoSymbol symbol)
    {
        ArgumentNullException.ThrowIfNull(station);
        ArgumentNullException.ThrowIfNull(symbol);
        (StationName, Station, Symbol, PlcAddress, Comment) = (station.Name, station.Address, symbol.Symbol, symbol.Address, symbol.Description);
    }

    public string StationName { get; }

    public Station Station { get; }

    public string Symbol { get; }

    public PlcAddress PlcAddress { get; }

    public string Address => PlcAddress.ToString();

    public string Comment { get; }

    /// <summary>The bit as last read; null when never read. A stale value keeps the last good read.</summary>
    public bool? Value
    {
        get => _value;
        private set
        {
            if (SetProperty(ref _value, value))
            {
                OnPropertyChanged(nameof(State));
            }
        }
    }

    public ValueQuality Quality
    {
        get => _quality;
        private set
        {
            if (SetProperty(ref _quality, value))
            {
                OnPropertyChanged(nameof(State));
            }
        }
    }

    /// <summary>Why the value is stale or bad (the link's error); null when good.</summary>
    public string? QualityText
    {
        get => _qualityText;
        private set => SetProperty(ref _qualityText, value);
    }

    public LampState State => (Quality, Value) switch
    {
        (ValueQuality.Good, true) => LampState.On,
        (ValueQuality.Good, false) => LampState.Off,
        (ValueQuality.Stale, true) => LampState.StaleOn,
        (ValueQuality.Stale, false) => LampState.StaleOff,
        _ => LampState.Bad,
    };

    internal void Apply(PolledValue value)
    {
        Value = value.AsBit;
        Quality = value.Quality;
        QualityText = value.Quality == ValueQuality.Good ? null : value.Error;
        OnApplied();
    }

    /// <summary>Lets an output row react to a new read-back (it clears "writing…").</summary>
    protected virtual void OnApplied()
    {
    }
}
