using System.Collections.Immutable;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Stl.Freeport;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// A baud rate and character format. Character time = (1 start + 8 data + parity + 1 stop) / baud (docs/protocol-v2.md
/// §7; S7-200 Freeport always sends one stop bit): 10 bits for 8N1, 11 for 8E1.
/// </summary>
internal sealed record LineSetting(int Baud, string Format, int BitsPerCharacter)
{
    public static ImmutableArray<LineSetting> Modeled { get; } =
        [new(9600, "8N1", 10), new(9600, "8E1", 11), new(38400, "8N1", 10), new(38400, "8E1", 11)];

    public double CharacterMs => BitsPerCharacter * 1000.0 / Baud;

    /// <summary>The same setting for the simulated PLC's port: 8 data bits, even parity when a character has 11 bits.</summary>
    public LineSettings Settings => new(Baud, BitsPerCharacter == 11 ? Parity.Even : Parity.None, 8);

    public override string ToString() => $"{Baud} {Format}";
}
