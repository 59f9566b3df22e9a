namespace OperatorPanel.Simulator.Stl.Freeport;

/// <summary>An XMT in progress: its burst on the line and the next character to leave.</summary>
internal sealed class Transmission(WireBurst burst)
{
    public WireBurst Burst { get; } = burst;

    /// <summary>Characters already sent (for a break: 0 until it ends).</summary>
    public int Sent { get; set; }

    /// <summary>A PPI telegram the CPU's PPI side sends: no transmit-complete event, no SM4.5/SM4.6, survives leaving Freeport.</summary>
    public bool IsPpi { get; init; }

    public bool IsLast => Burst.IsBreak || Sent == Burst.Count - 1;

    /// <summary>When the next character's stop bit ends (for a break, the end of the 16 bit times).</summary>
    public TimeSpan NextAt => Burst.IsBreak ? Burst.End : Burst.CharacterEnd(Sent);
}
