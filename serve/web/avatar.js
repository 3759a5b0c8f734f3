// PLACEHOLDER of the avatar page's script (the serve25-page helper replaces it).
document.getElementById('status').textContent = 'fapcast serve: placeholder script loaded';
