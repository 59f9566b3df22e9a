namespace OperatorPanel.Simulator.Stl.Execution;

/// <summary>
/// The real-time clock on the simulated time (A5E00307987-04 chapter 6, "Clock Instructions"): TODR T / TODW T read
/// and write 8 bytes, all BCD: year (00-99), month, day, hour, minute, second, 00, day of week (1 = Sunday ... 7 =
/// Saturday). The clock runs from <see cref="Start"/> with the CPU's simulated time; TODW moves it. Invalid data leaves
/// the clock as it was (the CPU reports non-fatal error 0007, TOD data error).
/// </summary>
internal sealed class StlRealTimeClock(StlTime time)
{
    private TimeSpan _offset;

    /// <summary>The date and time the clock shows at simulated time zero.</summary>
    public DateTime Start { get; set; } = new(2000, 1, 1, 0, 0, 0, DateTimeKind.Unspecified);

    /// <summary>What TODR reads now.</summary>
    public DateTime Now => Start + _offset + StlTime.ToTimeSpan(time.Now);

    /// <summary>TODR: the 8 BCD bytes of <see cref="Now"/>.</summary>
    public void Read(Span<byte> target)
    {
        var clock = Now;
        byte[] bytes = [Bcd(clock.Year % 100), Bcd(clock.Month), Bcd(clock.Day), Bcd(clock.Hour), Bcd(clock.Minute), Bcd(clock.Second), 0, Bcd((int)clock.DayOfWeek + 1)];
        bytes.CopyTo(target);
    }

    /// <summary>TODW: sets the clock from 8 BCD bytes; false (ENO = 0) for a digit that is not BCD or a date that does not exist.</summary>
    public bool TryWrite(ReadOnlySpan<byte> b)
    {
        for (var i = 0; i < 6; i++)
        {
            if (!IsBcd(b[i]))
            {
                return false;
            }
        }

        var (year, month, day, hour, minute, second) = (2000 + FromBcd(b[0]), FromBcd(b[1]), FromBcd(b[2]), FromBcd(b[3]), FromBcd(b[4]), FromBcd(b[5]));
        if (month is < 1 or > 12 || day < 1 || day > DateTime.DaysInMonth(year, month) || hour > 23 || minute > 59 || second > 59)
        {
            return false;
        }

        _offset = new DateTime(year, month, day, hour, minute, second, DateTimeKind.Unspecified) - Start - StlTime.ToTimeSpan(time.Now);
        return true;
    }

    private static byte Bcd(int value) => (byte)(((value / 10) << 4) | (value % 10));

    private static int FromBcd(byte value) => ((value >> 4) * 10) + (value & 0x0F);

    private static bool IsBcd(byte value) => (value >> 4) <= 9 && (value & 0x0F) <= 9;
}
