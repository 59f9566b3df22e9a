namespace OperatorPanel.Core.Transport;

/// <summary>
/// Serial line settings for one bus. S7-200 Freeport always uses one stop bit and 7 or 8 data bits (seed 002,
/// Table C-11), so those are the only values a project may hold; the transport itself accepts what the OS accepts.
/// </summary>
public sealed record SerialSettings
{
    /// <summary>"COM3" on Windows, a device path such as "/dev/ttyUSB0" or "/dev/pts/4" on Linux.</summary>
    public required string PortName { get; init; }

    public int BaudRate { get; init; } = 9600;

    public Parity Parity { get; init; } = Parity.None;

    public int DataBits { get; init; } = 8;

    public int StopBits { get; init; } = 1;

    public LinkKind Kind { get; init; } = LinkKind.Cable;

    /// <summary>Freeport (the handler) or PPI (no program of ours in the PLC); the same for every station on the port.</summary>
    public LinkProtocol Protocol { get; init; } = LinkProtocol.Freeport;

    /// <summary>The line settings as technicians write them: "9600 8N1".</summary>
    public string LineText => string.Create(
        System.Globalization.CultureInfo.InvariantCulture, $"{BaudRate} {DataBits}{Parity.ToString()[0]}{StopBits}");

    /// <summary>Bits on the wire per character: start + data + parity + stop.</summary>
    public int BitsPerCharacter => 1 + DataBits + (Parity == Parity.None ? 0 : 1) + StopBits;

    /// <summary>Time one character occupies the line at <see cref="BaudRate"/>.</summary>
    public TimeSpan CharacterTime => TimeSpan.FromTicks(TimeSpan.TicksPerSecond * BitsPerCharacter / BaudRate);
}
