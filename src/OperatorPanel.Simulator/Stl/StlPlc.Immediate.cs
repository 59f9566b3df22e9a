namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Immediate I/O (A5E00307987-04 chapter 6, "Bit Logic Instructions": LDI, LDNI, AI, ANI, OI, ONI, =I, SI, RI;
/// "Move Instructions": BIR, BIW): an immediate contact reads the physical input and leaves the process image alone;
/// an immediate output writes the physical output and the process image together.
/// </summary>
public sealed partial class StlPlc
{
    private bool ReadPhysicalInput(StlLoc loc) => ((InputImage[loc.Offset] >> loc.Bit) & 1) != 0;

    /// <summary>=I (count 1 with Top), SI/RI Q, N: N bits from the operand on, image and physical output.</summary>
    private void WriteImmediate(StlLoc loc, int count, bool value)
    {
        var first = (loc.Offset * 8) + loc.Bit;
        for (var n = first; n < first + count && n < OutputImage.Length * 8; n++)
        {
            var mask = (byte)(1 << (n % 8));
            Memory.Q[n / 8] = value ? (byte)(Memory.Q[n / 8] | mask) : (byte)(Memory.Q[n / 8] & ~mask);
            OutputImage[n / 8] = value ? (byte)(OutputImage[n / 8] | mask) : (byte)(OutputImage[n / 8] & ~mask);
        }
    }

    private void WriteOutputByteImmediate(StlLoc loc, byte value)
    {
        Memory.Q[loc.Offset] = value;
        OutputImage[loc.Offset] = value;
    }
}
