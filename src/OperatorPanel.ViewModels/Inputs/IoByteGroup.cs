namespace OperatorPanel.ViewModels.Inputs;

/// <summary>The used bits of one I or Q byte of one station, in bit order: how the panel lays lamps out (IB0, IB1...).</summary>
public sealed class IoByteGroup<T>(string stationName, string byteAddress, IReadOnlyList<T> points)
    where T : IoPointViewModel
{
    public string StationName { get; } = stationName;

    /// <summary>"IB0", "QB1".</summary>
    public string ByteAddress { get; } = byteAddress;

    public string Title => $"{StationName} {ByteAddress}";

    public IReadOnlyList<T> Points { get; } = points;
}
