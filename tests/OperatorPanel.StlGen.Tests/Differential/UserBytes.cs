using OperatorPanel.Core.Protocol;
using OperatorPanel.Stl;
using OperatorPanel.StlGen.Merge;

namespace OperatorPanel.StlGen.Tests.Differential;

/// <summary>
/// The Q, M, V and SM bytes a user's program reads or writes, read with the merge's <see cref="InstructionOperands"/>
/// (block operands with their counts). Its code changes them beside the handler, so the reference model cannot know
/// them: a differential run of a merged program keeps its random requests off these bytes. Inputs stay comparable
/// (the user's program only reads them).
/// </summary>
internal sealed class UserBytes
{
    private readonly HashSet<(ProtocolArea Area, int Byte)> _bytes = [];

    public static UserBytes None { get; } = new();

    public int Count => _bytes.Count;

    public static UserBytes Of(string userAwl)
    {
        var program = AwlParser.Parse(userAwl).Program;
        var user = new UserBytes();
        foreach (var use in program.Blocks.SelectMany(b => b.Instructions).SelectMany(i => InstructionOperands.Uses(i, program)))
        {
            if (use.Operand.Kind == AwlOperandKind.Address && Area(use.Operand) is { } area)
            {
                var (first, last) = use.Bytes;
                for (var b = first; b <= last; b++)
                {
                    user._bytes.Add((area, b));
                }
            }
        }

        return user;
    }

    public bool Touches(ProtocolArea area, int first, int last) =>
        Enumerable.Range(first, Math.Max(0, last - first + 1)).Any(b => _bytes.Contains((area, b)));

    private static ProtocolArea? Area(AwlOperand operand) => operand.Area switch
    {
        Core.Addressing.MemoryArea.Q => ProtocolArea.Q,
        Core.Addressing.MemoryArea.M => ProtocolArea.M,
        Core.Addressing.MemoryArea.V => ProtocolArea.V,
        Core.Addressing.MemoryArea.SM => ProtocolArea.SM,
        _ => null,
    };
}
