using OperatorPanel.Simulator.Stl.Execution;

namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>
/// Compares (C233-01 p. 9-10): LD pushes the result, A ANDs and O ORs it into the top of the stack. Bytes compare
/// unsigned, words and double words signed, reals by IEEE rules. The relation is in op.N (0 =, 1 &lt;&gt;, 2 &lt;,
/// 3 &lt;=, 4 &gt;, 5 &gt;=), the width in op.Width.
/// </summary>
internal static class CompareInstructions
{
    public static void Load(StlMachine m, StlOp op) => m.Logic.Push(Integer(m, op));

    public static void And(StlMachine m, StlOp op) => m.Logic.And(Integer(m, op));

    public static void Or(StlMachine m, StlOp op) => m.Logic.Or(Integer(m, op));

    public static void LoadReal(StlMachine m, StlOp op) => m.Logic.Push(Real(m, op));

    public static void AndReal(StlMachine m, StlOp op) => m.Logic.And(Real(m, op));

    public static void OrReal(StlMachine m, StlOp op) => m.Logic.Or(Real(m, op));

    /// <summary>The relation of a compare mnemonic's tail ("=", "&lt;&gt;", ...) as op.N; null for none.</summary>
    public static int? RelationOf(string relation)
    {
        var index = Array.IndexOf(OperatorPanel.Stl.Instructions.StlInstructionTable.Relations, relation);
        return index < 0 ? null : index;
    }

    public static bool Holds<T>(int relation, T a, T b)
        where T : System.Numerics.INumber<T> => relation switch
        {
            0 => a == b,
            1 => a != b,
            2 => a < b,
            3 => a <= b,
            4 => a > b,
            _ => a >= b,
        };

    private static bool Integer(StlMachine m, StlOp op)
    {
        long a = m.Read(op.A!, op.Width);
        long b = m.Read(op.B!, op.Width);
        if (op.Width == 2)
        {
            (a, b) = ((short)a, (short)b);
        }
        else if (op.Width == 4)
        {
            (a, b) = ((int)a, (int)b);
        }

        return Holds(op.N, a, b);
    }

    private static bool Real(StlMachine m, StlOp op) => Holds(op.N, m.ReadReal(op.A!), m.ReadReal(op.B!));
}
