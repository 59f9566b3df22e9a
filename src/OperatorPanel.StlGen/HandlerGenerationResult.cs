using System.Collections.Immutable;
using OperatorPanel.StlGen.Diagnostics;
using OperatorPanel.StlGen.Model;

namespace OperatorPanel.StlGen;

/// <summary>
/// The generated handler: the .awl program, the symbol table to paste into Micro/WIN, the technician's notes, and the
/// static figures; or, for impossible settings, only the diagnostics (every text empty, no program).
/// </summary>
public sealed record HandlerGenerationResult(
    ImmutableArray<StlDiagnostic> Diagnostics,
    StlProgram? Program,
    HandlerStats? Stats,
    string AwlText,
    string SymbolTableText,
    string TechnicianText)
{
    public bool Ok => Program is not null;
}
