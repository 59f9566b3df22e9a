using System.Collections.Immutable;

namespace OperatorPanel.Core.Writes;

/// <summary>A write's outcome and the bytes the PLC holds at its address now (the whole byte for a bit; default when none came back).</summary>
internal readonly record struct WriteResult(WriteOutcome Outcome, ImmutableArray<byte> ReadBack);
