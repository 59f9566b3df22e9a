namespace OperatorPanel.Core.Protocol.V3;

/// <summary>Why bytes are not a v3 frame (or not the answer to the request sent).</summary>
public enum DecodeError
{
    None,

    /// <summary>The first byte is not '&lt;'.</summary>
    BadStart,

    /// <summary>Not LEN bytes, more than 255, or LEN too small for the head and the check.</summary>
    BadLength,

    /// <summary>The last 4 bytes are not the check of the bytes before them.</summary>
    CheckMismatch,

    /// <summary>A request whose STATION is not 1-126, or whose CMD is 0; a reply whose STATUS lacks bit 7.</summary>
    BadHeader,

    /// <summary>A reply whose REQCHECK is not the check of the request sent: it answers another frame.</summary>
    RequestCheckMismatch,

    /// <summary>A reply whose payload does not have the length its request and STATUS call for.</summary>
    BadPayload,
}
