using OperatorPanel.Simulator.Stl.Operations;

namespace OperatorPanel.Simulator.Stl.Execution;

/// <summary>One of T0-T255: current value (0-32767), timer bit, and the simulated time its last tick was counted from.</summary>
internal struct StlTimer
{
    public StlOpCode Kind;
    public short Value;
    public short Preset;
    public bool Bit;
    public bool Running;
    public bool LastInput;

    /// <summary>Simulated time (ns) the next tick is counted from; the part of a tick not yet counted is kept.</summary>
    public long Reference;
}
