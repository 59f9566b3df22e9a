using System.Diagnostics.CodeAnalysis;
using System.Globalization;

namespace OperatorPanel.Core.Addressing;

/// <summary>An RS-485 station address of a PLC running the handler, 1-126 (several PLCs share one bus).</summary>
public readonly record struct Station
{
    public const int Min = 1;
    public const int Max = 126;

    public Station(int address)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(address, Min);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(address, Max);
        Address = address;
    }

    public int Address { get; }

    public static bool TryCreate(int address, out Station station, [NotNullWhen(false)] out string? error)
    {
        if (address is < Min or > Max)
        {
            station = default;
            error = $"station address {address} is outside {Min}-{Max}";
            return false;
        }

        station = new Station(address);
        error = null;
        return true;
    }

    public override string ToString() => "station " + Address.ToString(CultureInfo.InvariantCulture);
}
