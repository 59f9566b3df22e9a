using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Values;

namespace OperatorPanel.Core.Projects;

/// <summary>A memory cell the panel monitors and, when writable, lets the operator change (seed 000 §7, wizard step 3).</summary>
/// <param name="Symbol">Unique within its station across inputs, outputs and tags (compared ignoring case).</param>
/// <param name="Address">A bit, byte, word or double word the link serves (M and V, or read-only I, Q and SM).</param>
/// <param name="Format">How the value is shown; it fits the address width (see <see cref="DisplayFormats.Fits"/>).</param>
/// <param name="Writable">True when the operator may write the cell; the address then passes AddressRules for writing.</param>
/// <param name="Description">Free comment for the operator; may be empty.</param>
/// <remarks>
/// <see cref="Unit"/>, <see cref="Scale"/> and <see cref="Range"/> are optional ("unit", "scale", "min"/"max" in the file)
/// and init properties, so tags built in code and projects written before them keep their shape; so are
/// <see cref="Recorded"/> and <see cref="Deadband"/> ("record", "deadband", for the historian). Scale and range are
/// for numbers (unsigned, signed, float); the value shown, typed and range-checked is the scaled one (<see cref="TagValues"/>).
/// </remarks>
public sealed record ProjectTag(string Symbol, PlcAddress Address, DisplayFormat Format, bool Writable, string Description)
{
    /// <summary>The engineering unit shown after the value ("%", "ml", "bottles/min"); null when none.</summary>
    public string? Unit { get; init; }

    /// <summary>Raw PLC number to engineering value, linear; null shows the raw number.</summary>
    public TagScale? Scale { get; init; }

    /// <summary>What the operator may write, in engineering units; null when the address's width is the only limit.</summary>
    public TagRange? Range { get; init; }

    /// <summary>The historian records the tag (the default); false leaves it out of the history.</summary>
    public bool Recorded { get; init; } = true;

    /// <summary>
    /// The historian's deadband for this tag in the value's own units (as <see cref="Format"/> shows it): a change is
    /// recorded when the value moves by more than this from the value last recorded. Null: the project's
    /// <see cref="HistorySettings.DeadbandPercent"/>. Bits and codes (hex, binary, ASCII) record every change.
    /// </summary>
    public double? Deadband { get; init; }
}
