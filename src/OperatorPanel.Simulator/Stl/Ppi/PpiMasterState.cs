using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;

namespace OperatorPanel.Simulator.Stl.Ppi;

/// <summary>What a CPU remembers of one master (PROFIBUS spec part 4 p. 131: the FCB is kept per initiator address).</summary>
internal sealed class PpiMasterState
{
    /// <summary>The frame count bit of this master's last action frame (FCV = 0 frames set it too).</summary>
    public bool? LastFrameCount { get; set; }

    /// <summary>What the CPU answered to this master's last action frame, repeated when the same FCB comes again.</summary>
    public PpiFrame? LastReply { get; set; }

    /// <summary>A job acknowledged and waiting for the communication phase.</summary>
    public S7Job? Pending { get; set; }

    /// <summary>A job that could not be read, answered with this refusal (error class, code) in the communication phase.</summary>
    public (byte Class, byte Code)? PendingRefusal { get; set; }

    /// <summary>The answer PDU prepared in the communication phase, sent at the next poll.</summary>
    public byte[]? Ready { get; set; }
}
