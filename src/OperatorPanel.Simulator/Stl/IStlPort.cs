namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// One communication port of the simulated CPU as the STL program drives it: RCV and XMT on a buffer in V memory,
/// controlled by SMB30/SMB87-SMB94 (port 0) or SMB130/SMB187-SMB194 (port 1) (seed 002, Tables C-15 and C-16).
/// The engine calls it; the port reads its control bytes and writes its status bytes in the CPU's memory itself.
/// </summary>
public interface IStlPort
{
    /// <summary>0 or 1.</summary>
    int Number { get; }

    /// <summary>RCV: starts a receive into the buffer at V byte <paramref name="bufferOffset"/> (byte 0 = count), or ends the active one when SMB87 bit 7 is 0.</summary>
    void Receive(int bufferOffset);

    /// <summary>XMT: sends the characters of the buffer at V byte <paramref name="bufferOffset"/> (byte 0 = count).</summary>
    void Transmit(int bufferOffset);

    /// <summary>When the port next changes state on its own (a character arrives or leaves, a timer runs out); null when idle.</summary>
    TimeSpan? NextChange { get; }

    /// <summary>Runs the port up to <paramref name="now"/>, adding every interrupt event it raises on the way, in order.</summary>
    void AdvanceTo(TimeSpan now, ICollection<StlEvent> raised);

    /// <summary>The CPU left RUN (or was powered up): any receive or transmit ends and the port is back in PPI.</summary>
    void Reset();
}
