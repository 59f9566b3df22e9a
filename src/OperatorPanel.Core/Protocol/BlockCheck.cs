namespace OperatorPanel.Core.Protocol;

/// <summary>
/// The frame's block check: XOR of the ASCII codes of the body characters as sent (docs/protocol.md, "Block check").
/// Computed over characters, not decoded bytes, so the PLC can check a frame with one XORB loop over its receive
/// buffer before it converts anything (seed 001: "BCC is the XOR sum of ... data ... encoded ... into ASCII code").
/// </summary>
public static class BlockCheck
{
    public static byte Compute(ReadOnlySpan<byte> characters)
    {
        byte bcc = 0;
        foreach (var c in characters)
        {
            bcc ^= c;
        }

        return bcc;
    }
}
