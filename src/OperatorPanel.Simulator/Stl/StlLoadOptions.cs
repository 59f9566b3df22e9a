using OperatorPanel.Stl.Symbols;

namespace OperatorPanel.Simulator.Stl;

/// <summary>How strictly <see cref="StlProgramLoader"/> takes what the simulator cannot do.</summary>
public sealed record StlLoadOptions
{
    public static StlLoadOptions Default { get; } = new();

    /// <summary>
    /// Refuse, instead of warning about, instructions the simulator treats as doing nothing (HDEF, HSC, PLS) and
    /// interrupt events it never raises (high-speed counters, pulse outputs, T32/T96): <c>opanel stl run --strict</c>.
    /// </summary>
    public bool Strict { get; init; }

    /// <summary>
    /// The program's symbol table (<c>--symbols FILE</c>): symbolic operands become its addresses before the program is
    /// checked; a symbol it does not hold is an error naming the line and the symbol. Null: symbols are refused.
    /// </summary>
    public AwlSymbolTable? Symbols { get; init; }
}
