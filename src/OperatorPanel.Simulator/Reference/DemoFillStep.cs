namespace OperatorPanel.Simulator.Reference;

/// <summary>The steps of the filler's sequence; step n shows as bit n of StatusWord MW10.</summary>
internal enum DemoFillStep
{
    /// <summary>Bottle stop Q0.2 out, waiting for a bottle under the fill head (I0.6).</summary>
    WaitBottle,

    /// <summary>Fill head going down (Q0.3).</summary>
    HeadDown,

    /// <summary>Fill valve open (Q0.1) until the level probe (I1.2) or the fill time VW104 runs out.</summary>
    Filling,

    /// <summary>Fill head going up.</summary>
    HeadUp,

    /// <summary>Bottle stop in: the filled bottle leaves for the outfeed and the next one comes in.</summary>
    Release,
}
