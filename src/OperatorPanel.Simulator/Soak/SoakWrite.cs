using OperatorPanel.Core.Writes;

namespace OperatorPanel.Simulator.Soak;

/// <summary>The panel's <paramref name="Number"/>-th write (from 1): VD<paramref name="Offset"/> := <paramref name="Value"/>, and what the panel reported.</summary>
public sealed record SoakWrite(int Number, int Offset, uint Value, WriteOutcome Outcome);
