using CommunityToolkit.Mvvm.ComponentModel;
using OperatorPanel.Core.Projects;
using OperatorPanel.Historian.Recording;

namespace OperatorPanel.ViewModels.Trends;

/// <summary>A recorded value the Trends window can show: picked or not, its colour, its value now and at the cursor.</summary>
public sealed partial class TrendTagViewModel(string stationName, RecordedTag tag, uint color) : ObservableObject
{
    public RecordedTag Tag { get; } = tag;

    /// <summary>"Filler.TankLevel".</summary>
    public string Name { get; } = $"{stationName}.{tag.Symbol}";

    public string Address => Tag.Address.ToString();

    public uint Color { get; } = color;

    public string ColorHex => TrendPalette.Hex(Color);

    public bool IsBit => Tag.Format == DisplayFormat.Bool;

    /// <summary>Shown in the chart.</summary>
    [ObservableProperty]
    public partial bool IsSelected { get; set; }

    /// <summary>"512 (good)": the line's value now.</summary>
    [ObservableProperty]
    public partial string ValueText { get; internal set; } = "-";

    /// <summary>"498 (good)", "stale", "not recorded" at the cursor's time; empty without a cursor.</summary>
    [ObservableProperty]
    public partial string CursorText { get; internal set; } = string.Empty;
}
