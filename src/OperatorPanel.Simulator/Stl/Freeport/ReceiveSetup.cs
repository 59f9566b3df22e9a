namespace OperatorPanel.Simulator.Stl.Freeport;

/// <summary>
/// SMB87-SMB94 (SMB187-SMB194) as RCV reads them: control byte <c>en sc ec il c/m tmr bk 0</c>, start and end
/// character, idle time SMW90 and timer SMW92 in ms (big-endian), maximum count SMB94 (seed 002, Table C-16).
/// </summary>
internal sealed record ReceiveSetup(
    bool Enabled,
    bool UseStartCharacter,
    bool UseEndCharacter,
    bool UseIdleLine,
    bool IsMessageTimer,
    bool UseTimer,
    bool UseBreak,
    byte StartCharacter,
    byte EndCharacter,
    TimeSpan IdleTime,
    TimeSpan Timeout,
    int MaxCount)
{
    public static ReceiveSetup Read(byte[] sm, PortRegisters registers)
    {
        ArgumentNullException.ThrowIfNull(sm);
        ArgumentNullException.ThrowIfNull(registers);
        var control = sm[registers.ReceiveControl];
        return new ReceiveSetup(
            Enabled: (control & 0x80) != 0,
            UseStartCharacter: (control & 0x40) != 0,
            UseEndCharacter: (control & 0x20) != 0,
            UseIdleLine: (control & 0x10) != 0,
            IsMessageTimer: (control & 0x08) != 0,
            UseTimer: (control & 0x04) != 0,
            UseBreak: (control & 0x02) != 0,
            StartCharacter: sm[registers.StartCharacter],
            EndCharacter: sm[registers.EndCharacter],
            IdleTime: Milliseconds(sm, registers.IdleTime),
            Timeout: Milliseconds(sm, registers.TimerTime),
            MaxCount: sm[registers.MaxCount]);
    }

    /// <summary>
    /// Status r cases: no start condition (il, sc and bk all 0), "idle line and start character (illegal): il=1, sc=1,
    /// SMW90=0", SMB94 outside 1-255, and a timer of 0 ms (Table C-16). The end condition always includes SMB94.
    /// </summary>
    public bool IsValid =>
        MaxCount >= 1
        && (UseIdleLine || UseStartCharacter || UseBreak)
        && !(UseIdleLine && UseStartCharacter && IdleTime == TimeSpan.Zero)
        && !(UseTimer && Timeout == TimeSpan.Zero);

    private static TimeSpan Milliseconds(byte[] sm, int offset) =>
        TimeSpan.FromMilliseconds((sm[offset] << 8) | sm[offset + 1]);
}
