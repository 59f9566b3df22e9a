using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Projects;

/// <summary>A descriptive name shown instead of an input or output bit's address (seed 000 §7, wizard step 2).</summary>
/// <param name="Symbol">Unique within its station across inputs, outputs and tags (compared ignoring case).</param>
/// <param name="Address">An I bit for an input, a Q bit for an output.</param>
/// <param name="Description">Free comment for the operator; may be empty.</param>
public sealed record IoSymbol(string Symbol, PlcAddress Address, string Description);
