using System.Diagnostics.CodeAnalysis;
using System.Globalization;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Stl;

namespace OperatorPanel.Simulator.Stl.Run;

/// <summary>
/// A value put into the PLC during a run: <c>ADDR=VALUE</c> at the start, <c>ADDR=VALUE@TIME</c> at a simulated time
/// (250ms, 2s, 1.5s, 10m, 1h). I goes to the field inputs (the program sees it at its next scan); Q, M, V, SM, S and AIW are
/// written into memory as a programming device would. A value of a double word may be a real (VD0=1.5).
/// </summary>
public sealed record StlSetting(PlcAddress Address, uint Value, TimeSpan At)
{
    public static bool TryParse(string text, CpuProfile cpu, [NotNullWhen(true)] out StlSetting? setting, [NotNullWhen(false)] out string? error)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        setting = null;
        var parts = (text ?? string.Empty).Split('=', 2, StringSplitOptions.TrimEntries);
        if (parts.Length != 2 || parts[1].Length == 0)
        {
            error = $"'{text}': write ADDR=VALUE or ADDR=VALUE@TIME (I0.0=1, VW10=-5, I0.1=1@2s)";
            return false;
        }

        var valueAndTime = parts[1].Split('@', 2, StringSplitOptions.TrimEntries);
        var at = TimeSpan.Zero;
        if (!PlcAddress.TryParse(parts[0], out var address, out var addressError))
        {
            error = $"'{text}': {addressError.Message}";
            return false;
        }

        if (AddressRules.Check(address, cpu) is { } refusal)
        {
            error = $"'{text}': {refusal.Message}";
            return false;
        }

        if (address.Area is MemoryArea.AQ or MemoryArea.T or MemoryArea.C || (address.Area == MemoryArea.SM && address.ByteOffset < cpu.ReadOnlySmBytes))
        {
            error = $"'{text}': {address} is written by the CPU or the program, not set from outside";
            return false;
        }

        if (valueAndTime.Length == 2 && !TryParseTime(valueAndTime[1], out at))
        {
            error = $"'{text}': '{valueAndTime[1]}' is not a time (write 250ms, 2s, 1.5s, 10m or 1h)";
            return false;
        }

        if (!TryParseValue(valueAndTime[0], address.Width, out var value))
        {
            error = $"'{text}': '{valueAndTime[0]}' does not fit a {address.Width.ToString().ToLowerInvariant()}{(address.Width == AccessWidth.Bit ? " (0 or 1)" : string.Empty)}";
            return false;
        }

        error = null;
        setting = new StlSetting(address, value, at);
        return true;
    }

    /// <summary>250ms, 2s, 1.5s, 10m, 2h, 0: a number and its unit (ms, s, m, h), at most a day.</summary>
    public static bool TryParseTime(string text, out TimeSpan time)
    {
        var t = (text ?? string.Empty).Trim().ToLowerInvariant();
        var (digits, scale) = t.EndsWith("ms", StringComparison.Ordinal) ? (t[..^2], 1.0)
            : t.EndsWith('s') ? (t[..^1], 1000.0)
            : t.EndsWith('m') ? (t[..^1], 60_000.0)
            : t.EndsWith('h') ? (t[..^1], 3_600_000.0)
            : (t, t == "0" ? 1.0 : double.NaN);
        var ok = double.TryParse(digits, NumberStyles.AllowDecimalPoint, CultureInfo.InvariantCulture, out var number) && !double.IsNaN(scale)
            && number * scale <= TimeSpan.FromDays(1).TotalMilliseconds;
        time = ok ? TimeSpan.FromMilliseconds(number * scale) : TimeSpan.Zero;
        return ok;
    }

    private static bool TryParseValue(string text, AccessWidth width, out uint value)
    {
        value = 0;
        if (!AwlOperand.TryParse(text, out var number, out _) || number.Kind != AwlOperandKind.Constant)
        {
            return false;
        }

        if (number.ConstantKind == AwlConstantKind.Real)
        {
            value = BitConverter.SingleToUInt32Bits((float)number.Real);
            return width == AccessWidth.DoubleWord;
        }

        var (min, max) = width switch
        {
            AccessWidth.Bit => (0L, 1L),
            AccessWidth.Byte => (sbyte.MinValue, byte.MaxValue),
            AccessWidth.Word => (short.MinValue, ushort.MaxValue),
            AccessWidth.DoubleWord => (int.MinValue, uint.MaxValue),
        };
        value = (uint)number.Integer;
        return number.ConstantKind == AwlConstantKind.Integer && number.Integer >= min && number.Integer <= max;
    }
}
