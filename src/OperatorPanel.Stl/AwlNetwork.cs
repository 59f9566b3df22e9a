using System.Collections.Immutable;

namespace OperatorPanel.Stl;

/// <summary>A <c>Network n // title</c> with its comment lines and instructions; number 0 when instructions precede any Network line.</summary>
public sealed record AwlNetwork(
    int Number, string Title, ImmutableArray<string> Comments, ImmutableArray<AwlInstruction> Instructions, int Line);
