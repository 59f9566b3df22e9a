namespace OperatorPanel.Simulator.Stl.Freeport;

/// <summary>
/// Characters one transmitter sends back to back from <see cref="Start"/>, each 1 start + data (LSB first) + parity +
/// 1 stop bit at its own settings; or a break, the line held low for 16 bit times (facts section 8). Every receiver on
/// the line reads the same burst, so appending characters that follow without a gap reaches all of them.
/// </summary>
internal sealed class WireBurst
{
    /// <summary>XMT with count 0 holds the line low "for 16-bit times at the current baud rate" (facts section 8).</summary>
    private const int BreakBits = 16;

    private readonly List<byte> _characters = [];

    public WireBurst(TimeSpan start, LineSettings settings, bool isBreak)
    {
        Start = start;
        Settings = settings;
        IsBreak = isBreak;
    }

    public TimeSpan Start { get; }

    public LineSettings Settings { get; }

    public bool IsBreak { get; }

    public int Count => _characters.Count;

    public TimeSpan End => IsBreak ? Start + Settings.Bits(BreakBits) : CharacterStart(Count);

    public byte this[int index] => _characters[index];

    public void Append(ReadOnlySpan<byte> characters)
    {
        if (IsBreak)
        {
            throw new InvalidOperationException("A break carries no characters.");
        }

        _characters.AddRange(characters);
    }

    /// <summary>The transmitter stopped (CPU left RUN, port back to PPI): characters not yet begun never go out.</summary>
    public void DropFrom(TimeSpan at)
    {
        var keep = IsBreak ? Count : FirstCharacterAtOrAfter(at);
        _characters.RemoveRange(keep, Count - keep);
    }

    public TimeSpan CharacterStart(int index) => Start + Settings.Bits((long)index * Settings.BitsPerCharacter);

    public TimeSpan CharacterEnd(int index) => CharacterStart(index + 1);

    public int FirstCharacterAtOrAfter(TimeSpan at)
    {
        if (at <= Start)
        {
            return 0;
        }

        var index = (int)Math.Min(Count, (at - Start).Ticks * Settings.Baud / (Settings.BitsPerCharacter * TimeSpan.TicksPerSecond));
        while (index < Count && CharacterStart(index) < at)
        {
            index++;
        }

        return index;
    }

    /// <summary>The line level this burst drives at <paramref name="at"/>: true = mark (idle, 1), false = space (0).</summary>
    public bool LevelAt(TimeSpan at)
    {
        if (at < Start || at >= End)
        {
            return true;
        }

        if (IsBreak)
        {
            return false;
        }

        var bitIndex = (at - Start).Ticks * Settings.Baud / TimeSpan.TicksPerSecond;
        var bitsPerCharacter = Settings.BitsPerCharacter;
        var character = _characters[(int)Math.Min(Count - 1, bitIndex / bitsPerCharacter)];
        var bit = (int)(bitIndex % bitsPerCharacter);
        return bit switch
        {
            0 => false,
            _ when bit <= Settings.DataBits => ((character >> (bit - 1)) & 1) != 0,
            _ when bit == Settings.DataBits + 1 && Settings.Parity != Core.Transport.Parity.None => ParityBit(character),
            _ => true,
        };
    }

    private bool ParityBit(byte character)
    {
        var data = Settings.DataBits == 7 ? character & 0x7F : character;
        var odd = (System.Numerics.BitOperations.PopCount((uint)data) & 1) != 0;
        return Settings.Parity == Core.Transport.Parity.Even ? odd : !odd;
    }
}
