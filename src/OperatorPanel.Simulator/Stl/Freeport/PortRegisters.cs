namespace OperatorPanel.Simulator.Stl.Freeport;

/// <summary>
/// Where one port's control and status live in SM, and its event numbers: port 0 SMB30, SMB86-SMB94, SM4.5, events
/// 8/9/23; port 1 SMB130, SMB186-SMB194, SM4.6, events 25/26/24 (seed 002 Tables C-5, C-11, C-16; facts section 5).
/// </summary>
internal sealed record PortRegisters(
    int Control,
    int Status,
    int TransmitIdleBit,
    int ReceiveCharacterEvent,
    int TransmitCompleteEvent,
    int ReceiveCompleteEvent)
{
    /// <summary>SMB2: the last character received in Freeport mode, shared by both ports (Table C-3).</summary>
    public const int ReceivedCharacter = 2;

    /// <summary>SMB3: bit 0 = parity error on that character (Table C-4).</summary>
    public const int ParityByte = 3;

    /// <summary>SMB4: bit 5 / bit 6 = transmitter idle on port 0 / 1 (Table C-5).</summary>
    public const int QueueByte = 4;

    public static PortRegisters For(int port) => port switch
    {
        0 => new PortRegisters(30, 86, 5, 8, 9, 23),
        1 => new PortRegisters(130, 186, 6, 25, 26, 24),
        _ => throw new ArgumentOutOfRangeException(nameof(port), port, "An S7-200 has port 0 and, on CPU 224XP/226, port 1."),
    };

    public int ReceiveControl => Status + 1;

    public int StartCharacter => Status + 2;

    public int EndCharacter => Status + 3;

    public int IdleTime => Status + 4;

    public int TimerTime => Status + 6;

    public int MaxCount => Status + 8;
}
