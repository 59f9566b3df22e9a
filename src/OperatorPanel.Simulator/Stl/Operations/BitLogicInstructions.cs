using OperatorPanel.Simulator.Stl.Execution;

namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>
/// Contacts, coils, the logic stack and edges (C233-01 p. 9-194, "Logic Stack Instructions"); immediate I/O
/// (A5E00307987-04 chapter 6, "Bit Logic Instructions": LDI, LDNI, AI, ANI, OI, ONI, =I, SI, RI): an immediate contact
/// reads the physical input and leaves the process image alone; an immediate output writes the physical output and the
/// process image together.
/// </summary>
internal static class BitLogicInstructions
{
    public static void Load(StlMachine m, StlOp op) => m.Logic.Push(m.ReadBit(op.A!));

    public static void LoadNot(StlMachine m, StlOp op) => m.Logic.Push(!m.ReadBit(op.A!));

    public static void And(StlMachine m, StlOp op) => m.Logic.And(m.ReadBit(op.A!));

    public static void AndNot(StlMachine m, StlOp op) => m.Logic.And(!m.ReadBit(op.A!));

    public static void Or(StlMachine m, StlOp op) => m.Logic.Or(m.ReadBit(op.A!));

    public static void OrNot(StlMachine m, StlOp op) => m.Logic.Or(!m.ReadBit(op.A!));

    public static void Not(StlMachine m, StlOp op) => m.Logic.Not();

    public static void RisingEdge(StlMachine m, StlOp op) => m.Edge(op.N, rising: true);

    public static void FallingEdge(StlMachine m, StlOp op) => m.Edge(op.N, rising: false);

    public static void LogicPush(StlMachine m, StlOp op) => m.Logic.PushCopy();

    public static void LogicRead(StlMachine m, StlOp op) => m.Logic.ReadSecond();

    public static void LogicPop(StlMachine m, StlOp op) => m.Logic.Pop();

    public static void AndLoad(StlMachine m, StlOp op) => m.Logic.AndLoad();

    public static void OrLoad(StlMachine m, StlOp op) => m.Logic.OrLoad();

    /// <summary>LDS N: a copy of stack level N pushed on top.</summary>
    public static void LoadStack(StlMachine m, StlOp op) => m.Logic.Push(m.Logic.Level((int)m.Read(op.A!, 1)));

    public static void AndEno(StlMachine m, StlOp op) => m.Logic.And(m.Eno);

    public static void Assign(StlMachine m, StlOp op) => m.WriteBit(op.A!, m.Logic.Top);

    public static void Set(StlMachine m, StlOp op) => m.WriteBits(op.A!, (int)m.Read(op.B!, 1), true);

    public static void Reset(StlMachine m, StlOp op) => m.WriteBits(op.A!, (int)m.Read(op.B!, 1), false);

    public static void NoOperation(StlMachine m, StlOp op)
    {
    }

    public static void LoadImmediate(StlMachine m, StlOp op) => m.Logic.Push(PhysicalInput(m, op.A!));

    public static void LoadNotImmediate(StlMachine m, StlOp op) => m.Logic.Push(!PhysicalInput(m, op.A!));

    public static void AndImmediate(StlMachine m, StlOp op) => m.Logic.And(PhysicalInput(m, op.A!));

    public static void AndNotImmediate(StlMachine m, StlOp op) => m.Logic.And(!PhysicalInput(m, op.A!));

    public static void OrImmediate(StlMachine m, StlOp op) => m.Logic.Or(PhysicalInput(m, op.A!));

    public static void OrNotImmediate(StlMachine m, StlOp op) => m.Logic.Or(!PhysicalInput(m, op.A!));

    public static void AssignImmediate(StlMachine m, StlOp op) => WriteImmediate(m, op.A!, 1, m.Logic.Top);

    public static void SetImmediate(StlMachine m, StlOp op) => WriteImmediate(m, op.A!, (int)m.Read(op.B!, 1), true);

    public static void ResetImmediate(StlMachine m, StlOp op) => WriteImmediate(m, op.A!, (int)m.Read(op.B!, 1), false);

    private static bool PhysicalInput(StlMachine m, StlLoc loc) => ((m.InputImage[loc.Offset] >> loc.Bit) & 1) != 0;

    /// <summary>=I (count 1 with the top of stack), SI/RI Q, N: N bits from the operand on, image and physical output.</summary>
    private static void WriteImmediate(StlMachine m, StlLoc loc, int count, bool value)
    {
        var q = m.Memory.Q;
        var output = m.OutputImage;
        var first = (loc.Offset * 8) + loc.Bit;
        for (var n = first; n < first + count && n < output.Length * 8; n++)
        {
            var mask = (byte)(1 << (n % 8));
            q[n / 8] = value ? (byte)(q[n / 8] | mask) : (byte)(q[n / 8] & ~mask);
            output[n / 8] = value ? (byte)(output[n / 8] | mask) : (byte)(output[n / 8] & ~mask);
        }
    }
}
