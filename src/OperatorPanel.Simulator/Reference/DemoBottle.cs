namespace OperatorPanel.Simulator.Reference;

/// <summary>One bottle on the demo line's conveyor.</summary>
internal sealed class DemoBottle(int serial, int position)
{
    /// <summary>Numbered in the order the bottles come onto the line; decides which ones fill slowly (DemoScript).</summary>
    public int Serial { get; } = serial;

    /// <summary>Millimetres along the conveyor from the infeed photo eye.</summary>
    public int Position { get; set; } = position;

    /// <summary>Product in the bottle, ml.</summary>
    public double Volume { get; set; }

    /// <summary>A bottle that fell over at the infeed: it lies across the photo eye until the operator lifts it.</summary>
    public bool Fallen { get; init; }

    /// <summary>How long a fallen bottle has lain at the infeed, ms.</summary>
    public int LyingMs { get; set; }
}
