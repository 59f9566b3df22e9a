using System.Collections.Immutable;

namespace OperatorPanel.StlGen.Model;

/// <summary>One network (one rung, so it also opens in LAD view): a title, comment lines for the technician, instructions.</summary>
public sealed record StlNetwork(string Title, ImmutableArray<string> Comments, ImmutableArray<StlInstruction> Instructions);
