using OperatorPanel.Simulator.Stl.Execution;

namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>
/// Moves, block moves, SWAP, and the immediate byte moves BIR/BIW (A5E00307987-04 chapter 6, "Move Instructions"). A
/// block move takes <see cref="StlTiming.PerByte"/> per byte on top of its base time.
/// </summary>
internal static class MoveInstructions
{
    public static void Byte(StlMachine m, StlOp op) => m.Write(op.B!, 1, m.Read(op.A!, 1));

    public static void Word(StlMachine m, StlOp op) => m.Write(op.B!, 2, m.Read(op.A!, 2));

    /// <summary>MOVD and MOVR: four bytes as they are.</summary>
    public static void DoubleWord(StlMachine m, StlOp op) => m.Write(op.B!, 4, m.Read(op.A!, 4));

    public static void BlockOfBytes(StlMachine m, StlOp op) => BlockMove(m, op, 1);

    public static void BlockOfWords(StlMachine m, StlOp op) => BlockMove(m, op, 2);

    public static void BlockOfDoubleWords(StlMachine m, StlOp op) => BlockMove(m, op, 4);

    public static void Swap(StlMachine m, StlOp op)
    {
        var word = m.Read(op.A!, 2);
        m.Write(op.A!, 2, ((word & 0xFF) << 8) | (word >> 8));
    }

    /// <summary>BIR IN, OUT: the physical input byte, not the process image.</summary>
    public static void ReadInputImmediate(StlMachine m, StlOp op) => m.Write(op.B!, 1, m.InputImage[op.A!.Offset]);

    /// <summary>BIW IN, OUT: the physical output byte and the process image together.</summary>
    public static void WriteOutputImmediate(StlMachine m, StlOp op)
    {
        var value = (byte)m.Read(op.A!, 1);
        m.Memory.Q[op.B!.Offset] = value;
        m.OutputImage[op.B.Offset] = value;
    }

    private static void BlockMove(StlMachine m, StlOp op, int unit)
    {
        var count = (int)m.Read(op.C!, 1) * unit;
        if (m.TrySpan(op.A!, count, out var from, out var fromOffset) && m.TrySpan(op.B!, count, out var to, out var toOffset))
        {
            Array.Copy(from, fromOffset, to, toOffset, count);
        }

        m.Charge(count * StlTiming.PerByte);
    }
}
