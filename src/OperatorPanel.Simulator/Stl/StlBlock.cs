using OperatorPanel.Stl;

namespace OperatorPanel.Simulator.Stl;

/// <summary>One loaded program organisation unit: its ops and the CALL parameters it takes.</summary>
internal sealed class StlBlock(AwlBlock source, int index)
{
    public AwlBlock Source { get; } = source;

    public int Index { get; } = index;

    public string Name => Source.Name;

    public AwlBlockKind Kind => Source.Kind;

    public StlOp[] Ops { get; set; } = [];

    /// <summary>IN, IN_OUT and OUT locals in order: what a CALL passes.</summary>
    public List<(StlLoc Formal, int Bytes, AwlVariableSection Section, bool IsBit)> Formals { get; } = [];
}
