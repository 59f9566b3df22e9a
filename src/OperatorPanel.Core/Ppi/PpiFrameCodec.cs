namespace OperatorPanel.Core.Ppi;

/// <summary>
/// Writes FDL telegrams as bytes (PROFIBUS telegram formats, felser.ch "Telegram formats"; docs/ppi.md section 2).
/// The frame check sequence is the arithmetic sum, modulo 256, of DA, SA, FC and the data.
/// </summary>
public static class PpiFrameCodec
{
    public const byte StartFixed = 0x10;
    public const byte StartVariable = 0x68;
    public const byte StartToken = 0xDC;
    public const byte ShortAcknowledge = 0xE5;
    public const byte End = 0x16;

    /// <summary>Most data an SD2 telegram carries: LE = data + 3 runs 4-249 (Kipp &amp; Zonen COMBILOG manual p. 118).</summary>
    public const int MaxData = 246;

    /// <summary>Characters of an SD2 telegram around its data: 68 LE LEr 68 DA SA FC ... FCS 16.</summary>
    public const int VariableOverhead = 9;

    /// <summary>Characters of an SD1 telegram: 10 DA SA FC FCS 16.</summary>
    public const int FixedLength = 6;

    public static byte Checksum(ReadOnlySpan<byte> bytes)
    {
        var sum = 0;
        foreach (var b in bytes)
        {
            sum += b;
        }

        return (byte)sum;
    }

    public static byte[] Encode(PpiFrame frame)
    {
        ArgumentNullException.ThrowIfNull(frame);
        switch (frame.Kind)
        {
            case PpiFrameKind.ShortAcknowledge:
                return [ShortAcknowledge];
            case PpiFrameKind.Token:
                return [StartToken, frame.Destination, frame.Source];
            case PpiFrameKind.Fixed:
                byte[] header = [frame.Destination, frame.Source, frame.FunctionCode];
                return [StartFixed, .. header, Checksum(header), End];
            default:
                var data = frame.Data.AsSpan();
                var bytes = new byte[data.Length + VariableOverhead];
                var length = (byte)(data.Length + 3);
                (bytes[0], bytes[1], bytes[2], bytes[3]) = (StartVariable, length, length, StartVariable);
                (bytes[4], bytes[5], bytes[6]) = (frame.Destination, frame.Source, frame.FunctionCode);
                data.CopyTo(bytes.AsSpan(7));
                bytes[^2] = Checksum(bytes.AsSpan(4, length));
                bytes[^1] = End;
                return bytes;
        }
    }

    /// <summary>Characters <paramref name="frame"/> takes on the line.</summary>
    public static int Length(PpiFrame frame)
    {
        ArgumentNullException.ThrowIfNull(frame);
        return frame.Kind switch
        {
            PpiFrameKind.ShortAcknowledge => 1,
            PpiFrameKind.Token => 3,
            PpiFrameKind.Fixed => FixedLength,
            _ => frame.Data.Length + VariableOverhead,
        };
    }
}
