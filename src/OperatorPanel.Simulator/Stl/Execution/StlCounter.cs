namespace OperatorPanel.Simulator.Stl.Execution;

/// <summary>One of C0-C255: current value, counter bit, and the count inputs as the counter last saw them (for its edges).</summary>
internal struct StlCounter
{
    public short Value;
    public bool Bit;
    public bool LastUp;
    public bool LastDown;
}
