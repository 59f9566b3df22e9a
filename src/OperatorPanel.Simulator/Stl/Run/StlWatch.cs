using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Stl;

namespace OperatorPanel.Simulator.Stl.Run;

/// <summary>
/// An address to print after a run: I0.0 (0/1), VB10 (0-255), VW10 (INT), VD10 (DINT), VD10:REAL, T37 / C5 (current
/// value), T37.BIT / C5.BIT (0/1), AC0 (DINT). Read with <see cref="TryParse"/>.
/// </summary>
public sealed record StlWatch(string Text, AwlOperand Operand, bool IsBitOfTimerOrCounter, bool IsReal)
{
    private const string BitSuffix = ".BIT";
    private const string RealSuffix = ":REAL";

    public static bool TryParse(string text, CpuProfile cpu, [NotNullWhen(true)] out StlWatch? watch, [NotNullWhen(false)] out string? error)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        watch = null;
        var upper = (text ?? string.Empty).Trim().ToUpperInvariant();
        var isBit = upper.EndsWith(BitSuffix, StringComparison.Ordinal);
        var isReal = upper.EndsWith(RealSuffix, StringComparison.Ordinal);
        var core = isBit ? upper[..^BitSuffix.Length] : isReal ? upper[..^RealSuffix.Length] : upper;
        if (!AwlOperand.TryParse(core, out var operand, out error) || operand.Kind != AwlOperandKind.Address)
        {
            error = $"'{text}': {error ?? "not an address"} (print I0.0, VB10, VW10, VD10, VD10:real, T37, T37.bit, C5, C5.bit or AC0)";
            return false;
        }

        if (!TryCheck(operand, cpu, isBit, isReal, out error))
        {
            error = $"'{text}': {error}";
            return false;
        }

        watch = new StlWatch(upper, operand, isBit, isReal);
        return true;
    }

    private static bool TryCheck(AwlOperand operand, CpuProfile cpu, bool isBit, bool isReal, [NotNullWhen(false)] out string? error)
    {
        error = null;
        if (operand.Area is MemoryArea.T or MemoryArea.C)
        {
            error = operand.ByteOffset > 255 ? "timers and counters are numbered 0-255" : isReal ? ":real is for double words" : null;
        }
        else if (isBit)
        {
            error = ".bit is for timers and counters; write the bit address itself (Q0.0)";
        }
        else if (operand.Area == MemoryArea.AC)
        {
            error = operand.ByteOffset >= cpu.Accumulators ? $"the CPU has AC0-AC{cpu.Accumulators - 1}" : null;
        }
        else if (operand.Area is MemoryArea.HC or MemoryArea.L)
        {
            error = "high-speed counters and L memory are not printed";
        }
        else if (isReal && operand.Width != AccessWidth.DoubleWord)
        {
            error = ":real is for double words (VD10:real)";
        }
        else
        {
            var address = operand.Bit is { } bit
                ? PlcAddress.ForBit(operand.Area, operand.ByteOffset, bit)
                : PlcAddress.ForBytes(operand.Area, operand.ByteOffset, operand.Width);
            error = AddressRules.Check(address, cpu)?.Message;
        }

        return error is null;
    }
}
