namespace OperatorPanel.Simulator.Hosting;

/// <summary>
/// The stations of one RS-485 line in simulated time, whichever model answers (<see cref="ReferenceLine"/>: the plain C#
/// model; <see cref="StlLine"/>: the generated .awl in the interpreter). <see cref="SimulatedPlcHost"/> maps a
/// TimeProvider onto it: run to now, put the PC's bytes on the line at now, send what the stations have finished sending.
/// </summary>
public interface ISimulatedLine
{
    /// <summary>Simulated time the line has run to.</summary>
    TimeSpan Now { get; }

    /// <summary>Frames the stations received complete ('&lt;' .. '&gt;'), whether answered or not.</summary>
    int FramesReceived { get; }

    /// <summary>Reply frames the stations finished sending.</summary>
    int Replies { get; }

    /// <summary>When the next character will be ready to send, if the line knows; the host polls no later than this.</summary>
    TimeSpan? NextOutput { get; }

    /// <summary>Runs every station (and its demo process) to <paramref name="until"/>.</summary>
    void RunUntil(TimeSpan until);

    /// <summary>The PC starts sending <paramref name="characters"/> at <see cref="Now"/>.</summary>
    void Deliver(ReadOnlySpan<byte> characters);

    /// <summary>The characters the stations finished sending by <see cref="Now"/>, in order, each once.</summary>
    byte[] TakeTransmitted();
}
