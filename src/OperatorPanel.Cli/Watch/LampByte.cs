namespace OperatorPanel.Cli.Watch;

/// <summary>
/// The configured bits of one I or Q byte as a row of lamps, bit 0 first: ● on, ○ off, · no symbol, and ? unknown: not
/// read, or its reading not good (stale: the station stopped answering; bad: refused), never the last value as if current.
/// </summary>
internal sealed record LampByte(string Byte, string Lamps, IReadOnlyList<LampBit> Bits)
{
    public const char On = '●';
    public const char Off = '○';
    public const char Unknown = '?';
    public const char Unused = '·';
}

/// <summary>
/// One symbolised bit: address, symbol, its last reading (null when never read) and that reading's quality ("good",
/// "stale", "bad"), as a tag's value sits beside its quality: only a "good" bit is the PLC's state now.
/// </summary>
internal sealed record LampBit(string Address, string Symbol, bool? On, string Quality);
