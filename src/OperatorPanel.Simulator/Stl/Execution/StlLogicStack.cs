namespace OperatorPanel.Simulator.Stl.Execution;

/// <summary>
/// The logic stack: 9 bits, the top of stack in bit 0 (System Manual C79000-G7076-C233-01 p. 9-194, "Logic Stack
/// Instructions"). A box instruction runs only when the top is 1 (power flow).
/// </summary>
internal sealed class StlLogicStack
{
    private const uint Mask = 0x1FF;

    /// <summary>All nine levels; the top in bit 0. A CALL saves it and starts the callee with 1.</summary>
    public uint Bits { get; set; }

    public bool Top => (Bits & 1) != 0;

    /// <summary>The level <paramref name="depth"/> below the top (0 = the top).</summary>
    public bool Level(int depth) => ((Bits >> depth) & 1) != 0;

    /// <summary>LD: a new level on top; the bottom level falls off.</summary>
    public void Push(bool value) => Bits = ((Bits << 1) | (value ? 1u : 0u)) & Mask;

    /// <summary>A (and AI, AENO, compares): the top ANDed with <paramref name="value"/>.</summary>
    public void And(bool value) => Bits &= value ? ~0u : ~1u;

    /// <summary>O (and OI, compares): the top ORed with <paramref name="value"/>.</summary>
    public void Or(bool value) => Bits |= value ? 1u : 0u;

    public void Not() => Bits ^= 1;

    /// <summary>Replaces the top only.</summary>
    public void SetTop(bool value) => Bits = (Bits & ~1u) | (value ? 1u : 0u);

    /// <summary>LPS: duplicates the top.</summary>
    public void PushCopy() => Bits = ((Bits << 1) | (Bits & 1)) & Mask;

    /// <summary>LRD: the second level copied to the top.</summary>
    public void ReadSecond() => Bits = (Bits & ~1u) | ((Bits >> 1) & 1);

    /// <summary>LPP: pops the top.</summary>
    public void Pop() => Bits >>= 1;

    /// <summary>ALD: the top two levels ANDed into one.</summary>
    public void AndLoad() => Bits = (Bits >> 1) & (((Bits & 1) != 0) ? ~0u : ~1u);

    /// <summary>OLD: the top two levels ORed into one.</summary>
    public void OrLoad() => Bits = (Bits >> 1) | (Bits & 1);
}
