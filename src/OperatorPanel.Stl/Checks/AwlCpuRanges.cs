using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Stl.Checks;

/// <summary>
/// Whether an operand's memory is on the CPU and, when the instruction writes it, writable: VW5000 past a CPU 221's
/// VB2047, SMB200 past SMB179, AQW0 on a CPU 221 that has no analog outputs, Q20.0 past QB15 (Core
/// <see cref="AddressRules"/>, the CPU profiles' sizes), a write to SMB0-SMB29 or AIW. The one rule for every reader of
/// a program: <see cref="AwlProgramCheck"/> (so the merge and <c>opanel stl run</c> refuse the same operands) and the
/// simulator's compiler. Timers, counters, accumulators, high-speed counters and L memory have their own number
/// checks (the table's ranges, the block's locals).
/// </summary>
public static class AwlCpuRanges
{
    /// <summary>Null when the operand fits <paramref name="cpu"/>; otherwise the refusal and whether it is a range (AWL010) or a write to read-only memory (AWL008).</summary>
    public static (string Id, string Message)? Check(AwlOperand operand, bool written, CpuProfile cpu)
    {
        ArgumentNullException.ThrowIfNull(operand);
        ArgumentNullException.ThrowIfNull(cpu);
        var address = operand.Kind switch
        {
            AwlOperandKind.Address when Checked(operand.Area) => operand.Width == AccessWidth.Bit
                ? PlcAddress.ForBit(operand.Area, operand.ByteOffset, operand.Bit ?? 0)
                : PlcAddress.ForBytes(operand.Area, operand.ByteOffset, operand.Width),
            AwlOperandKind.Pointer when operand.Area is MemoryArea.I or MemoryArea.Q or MemoryArea.M or MemoryArea.V or MemoryArea.SM or MemoryArea.S => PlcAddress.ForBytes(operand.Area, operand.ByteOffset, AccessWidth.Byte),
            AwlOperandKind.Indirect when operand.Area == MemoryArea.V => PlcAddress.ForBytes(operand.Area, operand.ByteOffset, AccessWidth.DoubleWord),
            _ => (PlcAddress?)null,
        };
        if (address is not { } checkedAddress)
        {
            return null;
        }

        if (AddressRules.Check(checkedAddress, cpu) is { } refusal)
        {
            return (AwlCheckIds.OutOfRange, $"'{operand.Text}' is outside the CPU's ranges: {refusal.Message}");
        }

        // The pointer held by *VD10 is written by nobody here; only a direct operand the instruction writes can be read-only.
        var readOnly = operand.Kind == AwlOperandKind.Address
            && (operand.Area == MemoryArea.AI || (operand.Area == MemoryArea.SM && operand.ByteOffset < cpu.ReadOnlySmBytes));
        return written && readOnly
            ? (AwlCheckIds.OperandKind, $"'{operand.Text}' is read-only (SMB0-SMB{cpu.ReadOnlySmBytes - 1}, AIW): the CPU does not let a program write it")
            : null;
    }

    private static bool Checked(MemoryArea area) =>
        area is not (MemoryArea.T or MemoryArea.C or MemoryArea.AC or MemoryArea.HC or MemoryArea.L);
}
