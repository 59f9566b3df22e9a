using System.Globalization;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Simulator.Stl.Freeport;

/// <summary>
/// The character format one side of a Freeport line uses: baud, parity and 7 or 8 data bits, always one start and one
/// stop bit (seed 002 Table C-11; "One stop bit is generated for all configurations", facts section 4).
/// </summary>
public readonly record struct LineSettings(int Baud, Parity Parity, int DataBits)
{
    /// <summary>The handler's usual setting, SMB30 = 16#09 (docs/protocol-v2.md section 6).</summary>
    public static LineSettings Default { get; } = new(9600, Parity.None, 8);

    /// <summary>1 start + data + parity + 1 stop: 10 for 8N1, 11 for 8E1 (docs/protocol-v2.md section 7).</summary>
    public int BitsPerCharacter => 1 + DataBits + (Parity == Parity.None ? 0 : 1) + 1;

    public TimeSpan CharacterTime => Bits(BitsPerCharacter);

    /// <summary>
    /// The time <paramref name="bits"/> bit times take, rounded to the nearest tick once for the whole span, so ten
    /// characters at 9600 8N1 last 10.4167 ms and not ten times a rounded character time.
    /// </summary>
    public TimeSpan Bits(long bits) => TimeSpan.FromTicks(Round(bits * TimeSpan.TicksPerSecond, Baud));

    public static LineSettings From(SerialSettings serial)
    {
        ArgumentNullException.ThrowIfNull(serial);
        return new LineSettings(serial.BaudRate, serial.Parity, serial.DataBits);
    }

    /// <summary>
    /// Decodes SMB30/SMB130 (<c>pp d bbb mm</c>, seed 002 Table C-11) with the baud codes of <paramref name="cpu"/>'s
    /// revision (110/111 are 600/300 baud on early CPUs, 115.2k/57.6k on current ones). Returns false unless mm = 01
    /// (Freeport); in PPI modes bits 2-7 are ignored.
    /// </summary>
    public static bool TryFromControlByte(byte control, CpuProfile cpu, out LineSettings settings)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        settings = default;
        if ((control & 0b11) != 0b01)
        {
            return false;
        }

        var baudCode = (control >> 2) & 0b111;
        var baud = 0;
        foreach (var rate in cpu.FreeportBaudRates)
        {
            baud = rate.Code == baudCode ? rate.Baud : baud;
        }

        var parity = (control >> 6) switch
        {
            0b01 => Parity.Even,
            0b11 => Parity.Odd,
            _ => Parity.None,
        };
        settings = new LineSettings(baud, parity, (control & 0x20) != 0 ? 7 : 8);
        return baud > 0;
    }

    /// <summary>"9600 8N1", as <see cref="SerialSettings.LineText"/> writes it.</summary>
    public override string ToString() =>
        string.Create(CultureInfo.InvariantCulture, $"{Baud} {DataBits}{Parity.ToString()[0]}1");

    /// <summary>Half-bit steps, for sampling a bit in its middle.</summary>
    internal TimeSpan HalfBits(long halfBits) =>
        TimeSpan.FromTicks(Round(halfBits * TimeSpan.TicksPerSecond, 2L * Baud));

    private static long Round(long numerator, long denominator) => (numerator + (denominator / 2)) / denominator;
}
