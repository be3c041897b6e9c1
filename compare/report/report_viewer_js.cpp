// The two ways people compare renders, added to report.html in inline script (the page stays
// one offline file): flip (a pipeline's image and the reference swap in place, so the eye
// sees only what changed) and a magnifier (a zoomed, pixelated loupe under the cursor, so
// single pixels of an edge or a light's cut-off can be compared).
#include "compare/report/report_viewer_js.h"

namespace tp::cli {

namespace {

const char* kViewerStyle = R"(
figure img{cursor:crosshair}figure.flipped img{outline:3px solid #1f77b4;outline-offset:-3px}
.flip-state{font-weight:bold;color:#1f77b4}
#loupe{position:fixed;display:none;pointer-events:none;z-index:10;background:#fff;border:1px solid #333;
box-shadow:0 2px 8px rgba(0,0,0,.4);padding:2px;font-size:11px}
#loupe canvas{display:block;image-rendering:pixelated}
)";

// Pipeline images carry class "flip" and data-pipeline; the reference is #img-reference.
// Flip: a click on a pipeline's image, or F over it (F elsewhere: every pipeline image).
// Loupe: kLoupePixels x kLoupePixels image pixels around the hovered one, each drawn as a
// kLoupeZoom-wide block without smoothing; the hovered pixel is outlined.
const char* kViewerScript = R"(
(function(){
var ref=document.getElementById('img-reference');
var flips=Array.prototype.slice.call(document.querySelectorAll('img.flip'));
var N=21,Z=8,hovered=null,lastEvent=null;
function flip(img){
  if(!ref)return;
  var toRef=img.dataset.showing!=='reference';
  img.src=toRef?ref.getAttribute('src'):img.dataset.own;
  img.dataset.showing=toRef?'reference':'pipeline';
  img.parentNode.classList.toggle('flipped',toRef);
  var s=img.parentNode.querySelector('.flip-state');
  if(s)s.textContent=toRef?'showing the reference':'showing '+img.dataset.pipeline;
  if(hovered===img&&lastEvent)img.decode().then(function(){show(img,lastEvent);},function(){});
}
flips.forEach(function(img){
  img.dataset.own=img.getAttribute('src');
  img.dataset.showing='pipeline';
  img.addEventListener('click',function(){flip(img);});
});
document.addEventListener('keydown',function(e){
  if((e.key!=='f'&&e.key!=='F')||e.ctrlKey||e.metaKey||e.altKey)return; // Ctrl+F is the browser's find
  if(hovered&&hovered.classList.contains('flip'))flip(hovered);else flips.forEach(flip);
});
var loupe=document.createElement('div');loupe.id='loupe';
var canvas=document.createElement('canvas');canvas.width=canvas.height=N*Z;
var text=document.createElement('div');
loupe.appendChild(canvas);loupe.appendChild(text);document.body.appendChild(loupe);
function show(img,e){
  var r=img.getBoundingClientRect();
  if(!img.naturalWidth||r.width<=0||r.height<=0)return;
  var x=Math.min(img.naturalWidth-1,Math.max(0,Math.floor((e.clientX-r.left)/r.width*img.naturalWidth)));
  var y=Math.min(img.naturalHeight-1,Math.max(0,Math.floor((e.clientY-r.top)/r.height*img.naturalHeight)));
  var c=canvas.getContext('2d'),h=(N-1)/2;
  c.imageSmoothingEnabled=false;
  c.fillStyle='#888';c.fillRect(0,0,N*Z,N*Z);
  var sx=Math.max(0,x-h),sy=Math.max(0,y-h);
  var ex=Math.min(img.naturalWidth,x+h+1),ey=Math.min(img.naturalHeight,y+h+1);
  c.drawImage(img,sx,sy,ex-sx,ey-sy,(sx-x+h)*Z,(sy-y+h)*Z,(ex-sx)*Z,(ey-sy)*Z);
  c.strokeStyle='#fff';c.lineWidth=1;c.strokeRect(h*Z+0.5,h*Z+0.5,Z-1,Z-1);
  text.textContent=(img.dataset.showing==='reference'?'reference':img.alt)+'  pixel '+x+', '+y;
  loupe.dataset.x=x;loupe.dataset.y=y;
  loupe.style.display='block';
  var w=loupe.offsetWidth,hh=loupe.offsetHeight;
  var left=e.clientX+24,top=e.clientY+24;
  if(left+w>window.innerWidth)left=e.clientX-24-w;
  if(top+hh>window.innerHeight)top=e.clientY-24-hh;
  loupe.style.left=Math.max(0,left)+'px';loupe.style.top=Math.max(0,top)+'px';
}
document.querySelectorAll('figure img').forEach(function(img){
  img.addEventListener('mousemove',function(e){hovered=img;lastEvent=e;show(img,e);});
  img.addEventListener('mouseleave',function(){hovered=null;loupe.style.display='none';});
});
})();
)";

} // namespace

const char* reportViewerStyle() {
    return kViewerStyle;
}

std::string reportViewerScript() {
    return std::string("<script>") + kViewerScript + "</script>\n";
}

} // namespace tp::cli
