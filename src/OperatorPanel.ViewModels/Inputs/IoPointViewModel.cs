using CommunityToolkit.Mvvm.ComponentModel;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Inputs;

/// <summary>One symbolised I or Q bit as a lamp: the value shown is always the last one read from the PLC.</summary>
public abstract partial class IoPointViewModel : ObservableObject
{
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
    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(State))]
    public partial bool? Value { get; private set; }

    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(State))]
    public partial ValueQuality Quality { get; private set; } = ValueQuality.Bad;

    /// <summary>Why the value is stale or bad (the link's error); null when good.</summary>
    [ObservableProperty]
    [NotifyPropertyChangedFor(nameof(Details))]
    public partial string? QualityText { get; private set; } = "not read yet";

    /// <summary>
    /// The row's tooltip in the compact lamp list, where only address and symbol have room: "I0.0 StartButton", the
    /// comment, and why the value is not good (the lamp's dashed ring says that it is not).
    /// </summary>
    public string Details => string.Join(
        Environment.NewLine,
        new[] { $"{Address} {Symbol}", Comment, QualityText }.Where(line => !string.IsNullOrWhiteSpace(line)));

    public LampState State => (Quality, Value) switch
    {
        (ValueQuality.Good, true) => LampState.On,
        (ValueQuality.Good, false) => LampState.Off,
        (ValueQuality.Stale, true) => LampState.StaleOn,
        (ValueQuality.Stale, false) => LampState.StaleOff,
        (ValueQuality.Bad, _) or (_, null) => LampState.Bad,
    };

    /// <summary>The lamp's subscription to its address (PanelSession.Values): every value read, on the UI thread.</summary>
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
