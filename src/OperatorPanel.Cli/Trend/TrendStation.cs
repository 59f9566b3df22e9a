namespace OperatorPanel.Cli.Trend;

/// <summary>
/// A station whose tags a trend shows: its link state ("online", "offline", "unknown" before the first exchange) and its
/// last error as watch shows them, so a chart of nothing says why (the port is gone, nothing answers).
/// </summary>
internal sealed record TrendStation(string Name, int Station, string State, string? LastError)
{
    public bool Online => State == "online";

    /// <summary>"Filler offline, last error: station 2: serial port COM3: open failed ..." for a station not online; null when online.</summary>
    public string? Problem => Online ? null : LastError is null ? $"{Name} {State}" : $"{Name} {State}, last error: {LastError}";
}
