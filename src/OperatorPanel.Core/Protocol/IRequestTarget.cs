namespace OperatorPanel.Core.Protocol;

/// <summary>
/// What a station knows that the frame does not: its CPU's area sizes and which bytes the handler lets the panel
/// write (write mask, SMB0-SMB29, the handler's own SM bytes). Lets <see cref="RequestCodec.TryParse"/> apply the
/// checks of processing order step 6 in exactly the normative order.
/// </summary>
public interface IRequestTarget
{
    /// <summary>Size of a known area in bytes on this CPU (I 16, Q 16, M 32, V and SM per CPU).</summary>
    int AreaBytes(ProtocolArea area);

    /// <summary>True when every byte of the block may be written; a block touching one protected byte is refused whole.</summary>
    bool IsWritable(ProtocolArea area, int offset, int length);
}
