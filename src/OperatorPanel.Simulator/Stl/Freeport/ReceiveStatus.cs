namespace OperatorPanel.Simulator.Stl.Freeport;

/// <summary>SMB86/SMB186 receive message status bits <c>n r e 0 0 t c p</c> (seed 002, Table C-16).</summary>
internal static class ReceiveStatus
{
    public const byte UserDisable = 0x80;

    public const byte ParameterError = 0x40;

    public const byte EndCharacter = 0x20;

    public const byte TimerExpired = 0x04;

    public const byte MaxCount = 0x02;

    public const byte ParityError = 0x01;
}
