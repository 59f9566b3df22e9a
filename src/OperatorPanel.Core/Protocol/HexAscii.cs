namespace OperatorPanel.Core.Protocol;

/// <summary>
/// Uppercase hex digits only: the characters ATH accepts, 16#30-16#39 and 16#41-16#46 (research notes §9).
/// </summary>
internal static class HexAscii
{
    public static byte High(byte value) => Digit(value >> 4);

    public static byte Low(byte value) => Digit(value & 0x0F);

    public static bool IsDigit(byte c) => c is (>= (byte)'0' and <= (byte)'9') or (>= (byte)'A' and <= (byte)'F');

    /// <summary>The byte written by two digits that <see cref="IsDigit"/> has accepted.</summary>
    public static byte Pair(byte high, byte low) => (byte)((Value(high) << 4) | Value(low));

    private static byte Digit(int nibble) => (byte)(nibble < 10 ? '0' + nibble : 'A' + nibble - 10);

    private static int Value(byte c) => c <= '9' ? c - '0' : c - 'A' + 10;
}
