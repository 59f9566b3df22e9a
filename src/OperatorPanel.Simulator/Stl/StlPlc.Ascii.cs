namespace OperatorPanel.Simulator.Stl;

/// <summary>ATH and HTA (docs/sources/s7200-facts.md section 9): LEN counts ASCII characters / hex digits.</summary>
public sealed partial class StlPlc
{
    /// <summary>
    /// Legal characters are 16#30-39 and 16#41-46 only; an illegal one sets SM1.7 and leaves its nibble unchanged.
    /// An odd LEN leaves the low nibble of the last output byte unchanged.
    /// </summary>
    private long AsciiToHex(StlOp op)
    {
        var length = (int)Read(op.C!, 1);
        if (!TrySpan(op.A!, length, out var input, out var at) || !TrySpan(op.B!, (length + 1) / 2, out var output, out var to))
        {
            return op.Cost;
        }

        var illegal = false;
        for (var i = 0; i < length; i++)
        {
            var c = input[at + i];
            int nibble = c switch
            {
                >= 0x30 and <= 0x39 => c - 0x30,
                >= 0x41 and <= 0x46 => c - 0x41 + 10,
                _ => -1,
            };
            if (nibble < 0)
            {
                illegal = true;
                continue;
            }

            ref var target = ref output[to + (i / 2)];
            target = i % 2 == 0 ? (byte)((target & 0x0F) | (nibble << 4)) : (byte)((target & 0xF0) | nibble);
        }

        SetFlags(IllegalAscii, illegal ? IllegalAscii : (byte)0);
        return op.Cost + (length * StlTiming.PerByte);
    }

    private long HexToAscii(StlOp op)
    {
        var length = (int)Read(op.C!, 1);
        if (!TrySpan(op.A!, (length + 1) / 2, out var input, out var at) || !TrySpan(op.B!, length, out var output, out var to))
        {
            return op.Cost;
        }

        for (var i = 0; i < length; i++)
        {
            var source = input[at + (i / 2)];
            var nibble = i % 2 == 0 ? source >> 4 : source & 0x0F;
            output[to + i] = (byte)(nibble < 10 ? 0x30 + nibble : 0x41 + nibble - 10);
        }

        return op.Cost + (length * StlTiming.PerByte);
    }
}
