namespace OperatorPanel.Core.Protocol;

/// <summary>The FLAGS byte of READ CHANGES; any other bit set is error 06.</summary>
public static class ReadChangesFlags
{
    /// <summary>Bit 0: answer the whole list and renew the copy.</summary>
    public const byte Full = 0x01;
}
