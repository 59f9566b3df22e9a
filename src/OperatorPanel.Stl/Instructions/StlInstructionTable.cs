using System.Collections.Frozen;
using System.Collections.Immutable;
using System.Diagnostics.CodeAnalysis;

namespace OperatorPanel.Stl.Instructions;

/// <summary>
/// Every SIMATIC STL instruction of the S7-200 (CPU 221-226), one entry per mnemonic, as docs/stl-instructions.md lists
/// them with their sources. The only source of mnemonics and operand kinds for the parser's checks, the interpreter,
/// the generator's emitter and the merge's collision check.
/// </summary>
public static partial class StlInstructionTable
{
    private static readonly FrozenDictionary<string, StlInstructionSpec> ByMnemonic = Build();

    /// <summary>All entries, in the order docs/stl-instructions.md lists them.</summary>
    public static ImmutableArray<StlInstructionSpec> All { get; } = [.. Entries()];

    /// <summary>The entry for an upper-case mnemonic as written in STL: "MOVW", "LDW>=", "=I", "+I".</summary>
    public static bool TryGet(string mnemonic, [NotNullWhen(true)] out StlInstructionSpec? spec) =>
        ByMnemonic.TryGetValue(mnemonic, out spec);

    private static FrozenDictionary<string, StlInstructionSpec> Build()
    {
        var entries = new Dictionary<string, StlInstructionSpec>(StringComparer.Ordinal);
        foreach (var entry in Entries())
        {
            if (!entries.TryAdd(entry.Mnemonic, entry))
            {
                throw new InvalidOperationException($"the instruction table lists {entry.Mnemonic} twice");
            }
        }

        return entries.ToFrozenDictionary(StringComparer.Ordinal);
    }

    private static IEnumerable<StlInstructionSpec> Entries() =>
        BitLogic().Concat(Compares()).Concat(Moves()).Concat(Maths()).Concat(Logic()).Concat(ShiftsAndRotates())
            .Concat(Conversions()).Concat(TimersAndCounters()).Concat(Tables()).Concat(ProgramControl())
            .Concat(Interrupts()).Concat(Communication()).Concat(Clock()).Concat(Strings()).Concat(HighSpeed());

    private static StlInstructionSpec Entry(string mnemonic, StlInstructionGroup group, string source, params StlOperandSpec[] operands) =>
        new(mnemonic, group, [.. operands]) { Source = source };
}
