namespace OperatorPanel.Cli.Watch;

/// <summary>
/// The configured bits of one I or Q byte as a row of lamps, bit 0 first: ● on, ○ off, ? not read, · no symbol.
/// </summary>
internal sealed record LampByte(string Byte, string Lamps, IReadOnlyList<LampBit> Bits)
{
    public const char On = '●';
    public const char Off = '○';
    public const char Unknown = '?';
    public const char Unused = '·';
}

/// <summary>One symbolised bit: address, symbol and state (null when not read yet or unusable).</summary>
internal sealed record LampBit(string Address, string Symbol, bool? On);
