using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Core.Tests.Protocol;

/// <summary>A station with CPU 224 sizes (V 8192, SM 550) where I and SMB0-SMB29 are protected.</summary>
internal sealed class FakeTarget : IRequestTarget
{
    public int AreaBytes(ProtocolArea area) => area switch
    {
        ProtocolArea.I or ProtocolArea.Q => 16,
        ProtocolArea.M => 32,
        ProtocolArea.V => 8192,
        _ => 550,
    };

    public bool IsWritable(ProtocolArea area, int offset, int length) =>
        area != ProtocolArea.I && !(area == ProtocolArea.SM && offset < 30);
}
