namespace OperatorPanel.Simulator.Stl.Freeport;

/// <summary>
/// What a port's receiver made of the line: a character (or a break), when its start bit began, when it counted as
/// received (the end of its stop bit), and when the receiver looks for the next start bit. Error means a parity or
/// framing error (the S7-200 reports both as parity: SM3.0, SMB86 bit p).
/// </summary>
internal readonly record struct ReceivedCharacter(
    byte Value, TimeSpan Start, TimeSpan At, TimeSpan ReadyAt, bool Error, bool IsBreak);
