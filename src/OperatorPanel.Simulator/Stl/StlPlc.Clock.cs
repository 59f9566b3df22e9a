namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// The real-time clock on the simulated time (A5E00307987-04 chapter 6, "Clock Instructions"): TODR T / TODW T read
/// and write 8 bytes, all BCD: year (00-99), month, day, hour, minute, second, 00, day of week (1 = Sunday ... 7 =
/// Saturday). The clock runs from <see cref="ClockStart"/> with the CPU's simulated time; TODW moves it. Invalid data
/// sets ENO = 0 and leaves the clock as it was (the CPU reports non-fatal error 0007, TOD data error).
/// </summary>
public sealed partial class StlPlc
{
    private TimeSpan _clockOffset;

    /// <summary>The date and time the clock shows at simulated time zero.</summary>
    public DateTime ClockStart { get; set; } = new(2000, 1, 1, 0, 0, 0, DateTimeKind.Unspecified);

    /// <summary>What TODR reads now.</summary>
    public DateTime Clock => ClockStart + _clockOffset + Now;

    private static byte Bcd(int value) => (byte)(((value / 10) << 4) | (value % 10));

    private static int FromBcd(byte value) => ((value >> 4) * 10) + (value & 0x0F);

    private static bool IsBcd(byte value) => (value >> 4) <= 9 && (value & 0x0F) <= 9;

    private void ReadClock(StlOp op)
    {
        if (!TrySpan(op.A!, 8, out var area, out var offset))
        {
            return;
        }

        var clock = Clock;
        byte[] bytes = [Bcd(clock.Year % 100), Bcd(clock.Month), Bcd(clock.Day), Bcd(clock.Hour), Bcd(clock.Minute), Bcd(clock.Second), 0, Bcd((int)clock.DayOfWeek + 1)];
        bytes.CopyTo(area, offset);
    }

    private void WriteClock(StlOp op)
    {
        if (!TrySpan(op.A!, 8, out var area, out var offset))
        {
            return;
        }

        var b = area.AsSpan(offset, 8);
        for (var i = 0; i < 6; i++)
        {
            if (!IsBcd(b[i]))
            {
                _eno = false;
                return;
            }
        }

        var (year, month, day, hour, minute, second) = (2000 + FromBcd(b[0]), FromBcd(b[1]), FromBcd(b[2]), FromBcd(b[3]), FromBcd(b[4]), FromBcd(b[5]));
        if (month is < 1 or > 12 || day < 1 || day > DateTime.DaysInMonth(year, month) || hour > 23 || minute > 59 || second > 59)
        {
            _eno = false;
            return;
        }

        _clockOffset = new DateTime(year, month, day, hour, minute, second, DateTimeKind.Unspecified) - ClockStart - Now;
    }
}
